#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/CornerFix.h>
#include <toposlam/features/SegmentMerge.h>
#include <toposlam/features/SlopeDifferenceSplit.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

void CornerExtractorOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                const std::string& section) {
    dkThreshold = cfg.read_double(section, "dk_th", dkThreshold);
    alpha = cfg.read_double(section, "alpha", alpha);
    thetaThreshold = cfg.read_double(section, "theta_th", thetaThreshold);
    paperExact = cfg.read_bool(section, "paper_exact", paperExact);
    rangeNoiseStd = cfg.read_double(section, "range_noise_std", rangeNoiseStd);
    useScanStdError = cfg.read_bool(section, "use_scan_std_error", useScanStdError);
    noiseSigmas = cfg.read_double(section, "noise_sigmas", noiseSigmas);
    minBaseline =
        static_cast<unsigned>(cfg.read_int(section, "min_baseline", static_cast<int>(minBaseline)));
    minValidRange = cfg.read_double(section, "min_valid_range", minValidRange);
    jumps.loadFromConfigFile(cfg, section);
    assembly.loadFromConfigFile(cfg, section);
}

void CornerExtractorOptions::dumpToTextStream(std::ostream& out) const {
    out << "dk_th              = " << dkThreshold << "  (paper)\n"
        << "alpha              = " << alpha << "  (paper)\n"
        << "theta_th           = " << thetaThreshold << "  (paper)\n"
        << "paper_exact        = " << paperExact << "\n"
        << "range_noise_std    = " << rangeNoiseStd << "  (m)\n"
        << "use_scan_std_error = " << useScanStdError << "\n"
        << "noise_sigmas       = " << noiseSigmas << "\n"
        << "min_baseline       = " << minBaseline << "  (readings)\n"
        << "min_valid_range    = " << minValidRange << "  (m)\n";
    jumps.dumpToTextStream(out);
    assembly.dumpToTextStream(out);
}

std::string CornerExtractor::name() const {
    if (options.paperExact)
        return "corners-paper";
    return options.assembly.lineFit == LineFitMethod::TwoPoint ? "corners" : "corners-ls";
}

double CornerExtractor::rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const {
    if (options.paperExact)
        return 0;
    const double s = options.useScanStdError ? scan.stdError : options.rangeNoiseStd;
    return std::isfinite(s) && s > 0 ? s : 0.0;
}

void CornerExtractor::extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) {
    const bool paper = options.paperExact;
    const double sigma = rangeNoise(scan);
    points_.assign(scan, options.minValidRange);

    jumpDetector_.options = options.jumps;
    jumpDetector_.options.enabled = options.jumps.enabled && !paper;
    jumpDetector_.findRuns(points_, sigma, runs_);

    // Step 1.
    slopeDifference_.compute(points_, runs_, paper, options.alpha * options.dkThreshold, sigma,
                             options.noiseSigmas, std::max(1u, options.minBaseline));
    splitBySlopeDifference(points_, runs_, slopeDifference_, options.dkThreshold, paper, parts_,
                           peaks_);
    // Step 2.
    mergeSegments(points_, options.thetaThreshold, parts_);
    // Step 3.
    fixCorners(slopeDifference_, parts_);
    // Steps 4 and 5.
    assembly_.options = options.assembly;
    assembly_.options.minCornerTurn = std::atan(options.thetaThreshold);
    if (paper) {
        assembly_.options.rejectArcs = false;  // the paper assumes polygonal scenes
        assembly_.options.cornerAngleSigmas = 0;
        assembly_.options.splitNonLines = false;
    }
    assembly_.assemble(points_, parts_, sigma, out);
}

}  // namespace toposlam::features
