#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/CornerFix.h>
#include <toposlam/features/SegmentMerge.h>
#include <toposlam/features/SlopeDifferenceSplit.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

void CornerExtractorOptions::declare(config::OptionsSchema& s) {
    s.real("dk_th", dkThreshold, "", "breakpoint threshold on the slope difference |dk| (paper)")
        .above(0);
    s.real("alpha", alpha, "", "corners need |dk| > alpha * dk_th (paper)").above(0).atMost(1);
    s.real("theta_th", thetaThreshold, "",
           "merge neighbours when tan(angle between them) < theta_th (paper)")
        .above(0);
    s.flag("paper_exact", paperExact,
           "eq. (2) and the paper's rules exactly as printed, no noise model");
    s.real("range_noise_std", rangeNoiseStd, "m", "range noise when the scan does not state it")
        .atLeast(0);
    s.flag("use_scan_std_error", useScanStdError,
           "take the range noise from the scan's stdError field instead");
    s.real("noise_sigmas", noiseSigmas, "",
           "a corner must stand this many noise sigmas above noise in dk")
        .atLeast(0);
    s.integer("min_baseline", minBaseline, "readings",
              "readings each side over which dk is measured")
        .within(1, 1000);
    s.real("min_valid_range", minValidRange, "m",
           "readings at or below are invalid (as are NaN, <= 0, >= maxRange)")
        .atLeast(0);
    s.group("jump_", jumps);
    s.group("", assembly);
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
