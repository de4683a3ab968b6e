#include <toposlam/features/EndpointDetector.h>
#include <toposlam/features/LeastSquaresLineFit.h>
#include <toposlam/features/SegmentExtractor.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

using mrpt::math::TPoint2D;

void SegmentExtractorOptions::declare(config::OptionsSchema& s) {
    s.integer("median_window", medianWindow, "readings", "range median filter (odd; 1 = off)")
        .within(1, 15);
    s.require([this] { return medianWindow % 2 == 1; }, "median_window", "must be odd");
    s.angle("turn_threshold", turnThreshold, "convex below -it, concave above it (paper: 60)")
        .above(0)
        .below(180);
    s.flag("paper_exact", paperExact, "the paper's 4-tap turning sum, no noise model");
    s.real("range_noise_std", rangeNoiseStd, "m", "range noise when the scan does not state it")
        .atLeast(0);
    s.flag("use_scan_std_error", useScanStdError,
           "take the range noise from the scan's stdError field instead");
    s.real("noise_sigmas", noiseSigmas, "", "tolerances in range-noise sigmas").atLeast(0);
    s.real("min_valid_range", minValidRange, "m", "readings at or below are invalid").atLeast(0);
    s.group("jump_", jumps);
    s.integer("min_segment_points", minSegmentPoints, "readings",
              "of a convex-convex segment / concave-concave inliers")
        .within(2, 100000);
    s.real("max_line_residual", maxLineResidual, "m", "floor of the line tolerance (RMS)").above(0);
    s.angle("merge_angle", mergeAngle, "collinear convex-convex neighbours merge below it")
        .atLeast(0)
        .atMost(90);
    s.real("concave_inlier_ratio", concaveInlierRatio, "",
           "paper: > 30 % of the readings on the concave-concave line")
        .within(0, 1);
    s.real("inlier_distance", inlierDistance, "m", "floor of \"on the line\"").above(0);
    s.angle("arc_min_mean_angle", arcTest.minMeanAngle,
            "inscribed-angle arc test (Xavier et al. 2005): smallest mean angle")
        .above(0)
        .atMost(180);
    s.angle("arc_max_mean_angle", arcTest.maxMeanAngle, "... largest mean angle")
        .above(0)
        .atMost(180);
    s.angle("arc_max_angle_std", arcTest.maxAngleStd, "... largest std of the angles").atLeast(0);
    s.require([this] { return arcTest.minMeanAngle <= arcTest.maxMeanAngle; },
              "arc_min_mean_angle_deg", "must not exceed arc_max_mean_angle_deg");
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
