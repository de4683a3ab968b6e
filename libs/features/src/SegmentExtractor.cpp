#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/features/EndpointDetector.h>
#include <toposlam/features/LeastSquaresLineFit.h>
#include <toposlam/features/SegmentExtractor.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

using mrpt::math::TPoint2D;

void SegmentExtractorOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section) {
    medianWindow = static_cast<unsigned>(
        cfg.read_int(section, "median_window", static_cast<int>(medianWindow)));
    turnThreshold = cfg.read_double(section, "turn_threshold", turnThreshold);
    paperExact = cfg.read_bool(section, "paper_exact", paperExact);
    rangeNoiseStd = cfg.read_double(section, "range_noise_std", rangeNoiseStd);
    useScanStdError = cfg.read_bool(section, "use_scan_std_error", useScanStdError);
    noiseSigmas = cfg.read_double(section, "noise_sigmas", noiseSigmas);
    minValidRange = cfg.read_double(section, "min_valid_range", minValidRange);
    jumps.loadFromConfigFile(cfg, section);
    minSegmentPoints = static_cast<unsigned>(
        cfg.read_int(section, "min_segment_points", static_cast<int>(minSegmentPoints)));
    maxLineResidual = cfg.read_double(section, "max_line_residual", maxLineResidual);
    mergeAngle = cfg.read_double(section, "merge_angle", mergeAngle);
    concaveInlierRatio = cfg.read_double(section, "concave_inlier_ratio", concaveInlierRatio);
    inlierDistance = cfg.read_double(section, "inlier_distance", inlierDistance);
    arcTest.minMeanAngle = cfg.read_double(section, "arc_min_mean_angle", arcTest.minMeanAngle);
    arcTest.maxMeanAngle = cfg.read_double(section, "arc_max_mean_angle", arcTest.maxMeanAngle);
    arcTest.maxAngleStd = cfg.read_double(section, "arc_max_angle_std", arcTest.maxAngleStd);
}

void SegmentExtractorOptions::dumpToTextStream(std::ostream& out) const {
    out << "median_window        = " << medianWindow << "\n"
        << "turn_threshold       = " << turnThreshold << "  (rad)\n"
        << "paper_exact          = " << paperExact << "\n"
        << "range_noise_std      = " << rangeNoiseStd << "  (m)\n"
        << "use_scan_std_error   = " << useScanStdError << "\n"
        << "noise_sigmas         = " << noiseSigmas << "\n"
        << "min_valid_range      = " << minValidRange << "  (m)\n";
    jumps.dumpToTextStream(out);
    out << "min_segment_points   = " << minSegmentPoints << "\n"
        << "max_line_residual    = " << maxLineResidual << "  (m)\n"
        << "merge_angle          = " << mergeAngle << "  (rad)\n"
        << "concave_inlier_ratio = " << concaveInlierRatio << "\n"
        << "inlier_distance      = " << inlierDistance << "  (m)\n"
        << "arc_min_mean_angle   = " << arcTest.minMeanAngle << "  (rad)\n"
        << "arc_max_mean_angle   = " << arcTest.maxMeanAngle << "  (rad)\n"
        << "arc_max_angle_std    = " << arcTest.maxAngleStd << "  (rad)\n";
}

double SegmentExtractor::rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const {
    if (options.paperExact)
        return 0;
    const double s = options.useScanStdError ? scan.stdError : options.rangeNoiseStd;
    return std::isfinite(s) && s > 0 ? s : 0.0;
}

void SegmentExtractor::extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) {
    out.clear();
    const double sigma = rangeNoise(scan);
    raw_.assign(scan, options.minValidRange);
    filtered_.copyFrom(raw_);
    median_.window = options.medianWindow;
    median_.apply(filtered_);

    jumpDetector_.options = options.jumps;
    jumpDetector_.findRuns(filtered_, sigma, runs_);
    turning_.compute(filtered_, runs_, options.paperExact, sigma, options.noiseSigmas,
                     options.turnThreshold);
    detectEndpoints(filtered_, runs_, turning_, options.turnThreshold, endpoints_);

    convexSegments(sigma, out);
    concaveSegments(sigma, out);
    std::sort(
        out.segments.begin(), out.segments.end(), [](const LineSegment& a, const LineSegment& b) {
            return a.firstBeam != b.firstBeam ? a.firstBeam < b.firstBeam : a.lastBeam < b.lastBeam;
        });
    for (const Endpoint& e : endpoints_)
        out.endpoints.push_back(e);
    raw_.toScanOrder(out);
}

LineSegment SegmentExtractor::makeSegment(const LineFit& fit, std::size_t firstReading,
                                          std::size_t lastReading, const TPoint2D& from,
                                          const TPoint2D& to, EndpointType fromType,
                                          EndpointType toType) const {
    LineSegment s;
    s.line = fit.line;
    s.start = fit.line.project(from);
    s.end = fit.line.project(to);
    s.firstBeam = static_cast<std::uint32_t>(firstReading);
    s.lastBeam = static_cast<std::uint32_t>(lastReading);
    s.startType = fromType;
    s.endType = toType;
    s.residualRms = fit.residualRms;
    return s;
}

void SegmentExtractor::convexSegments(double sigma, ScanFeatures& out) {
    const double tolerance = std::max(options.maxLineResidual, options.noiseSigmas * sigma);
    const std::size_t minPoints = std::max(2u, options.minSegmentPoints);
    candidates_.clear();

    // Candidates between consecutive convex endpoints of a run with no concave one between.
    std::size_t e = 0;
    for (const PointRun& run : runs_) {
        while (e < endpoints_.size() && endpoints_[e].beam < run.begin)
            ++e;
        const Endpoint* prev = nullptr;
        bool concaveBetween = false;
        for (; e < endpoints_.size() && endpoints_[e].beam <= run.end; ++e) {
            const Endpoint& cur = endpoints_[e];
            if (cur.type == EndpointType::Concave) {
                concaveBetween = true;
                continue;
            }
            if (prev && !concaveBetween) {
                // Jump readings lie on the face; a convex corner reading may lie on either.
                const std::size_t fb =
                    prev->type == EndpointType::Jump ? prev->beam : prev->beam + 1;
                const std::size_t fe = cur.type == EndpointType::Jump ? cur.beam : cur.beam - 1;
                if (fe + 1 >= fb + minPoints) {
                    const LineFit fit = fitLeastSquares(raw_, fb, fe);
                    if (fit.ok && fit.residualRms <= tolerance &&
                        !options.arcTest.isArc(raw_, fb, fe)) {
                        candidates_.push_back({prev->beam, cur.beam, static_cast<std::uint32_t>(fb),
                                               static_cast<std::uint32_t>(fe), prev->type, cur.type,
                                               fit});
                    }
                }
            }
            prev = &cur;
            concaveBetween = false;
        }
    }

    // Merge neighbours that share a convex endpoint and are collinear (a spurious endpoint).
    const double sinMerge = std::sin(options.mergeAngle);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
        if (kept > 0) {
            Candidate& last = candidates_[kept - 1];
            const Candidate& cur = candidates_[i];
            const double cross =
                last.fit.normal.x * cur.fit.normal.y - last.fit.normal.y * cur.fit.normal.x;
            if (last.to == cur.from && std::abs(cross) < sinMerge) {
                const LineFit merged = fitLeastSquares(raw_, last.fitBegin, cur.fitEnd);
                if (merged.ok && merged.residualRms <= tolerance) {
                    last.to = cur.to;
                    last.toType = cur.toType;
                    last.fitEnd = cur.fitEnd;
                    last.fit = merged;
                    continue;
                }
            }
        }
        candidates_[kept++] = candidates_[i];
    }
    candidates_.resize(kept);

    for (const Candidate& c : candidates_) {
        out.segments.push_back(makeSegment(c.fit, c.from, c.to, filtered_.point(c.from),
                                           filtered_.point(c.to), c.fromType, c.toType));
    }
}

void SegmentExtractor::concaveSegments(double sigma, ScanFeatures& out) {
    const double tolerance = std::max(options.inlierDistance, options.noiseSigmas * sigma);
    const std::size_t minPoints = std::max(2u, options.minSegmentPoints);
    const Endpoint* prev = nullptr;
    for (const Endpoint& cur : endpoints_) {
        if (cur.type != EndpointType::Concave)
            continue;
        if (prev) {
            const TPoint2D a = filtered_.point(prev->beam), b = filtered_.point(cur.beam);
            const double length = std::sqrt(sq2(b.x - a.x, b.y - a.y));
            if (length > 0) {
                const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
                std::size_t total = 0, inliers = 0;
                PointSums sums;
                sums.reset(a.x, a.y);
                for (std::size_t k = prev->beam + 1; k < cur.beam; ++k) {
                    if (!raw_.valid(k))
                        continue;
                    ++total;
                    const double dx = raw_.x(k) - a.x, dy = raw_.y(k) - a.y;
                    const double t = dx * ux + dy * uy, d = std::abs(dy * ux - dx * uy);
                    if (d <= tolerance && t >= 0 && t <= length) {
                        ++inliers;
                        sums.add(raw_.x(k), raw_.y(k));
                    }
                }
                if (inliers >= minPoints &&
                    static_cast<double>(inliers) >
                        options.concaveInlierRatio * static_cast<double>(total)) {
                    const LineFit fit = fitLeastSquares(sums);
                    if (fit.ok) {
                        out.segments.push_back(makeSegment(fit, prev->beam, cur.beam, a, b,
                                                           EndpointType::Concave,
                                                           EndpointType::Concave));
                    }
                }
            }
        }
        prev = &cur;
    }
}

}  // namespace toposlam::features
