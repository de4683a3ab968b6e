#include <toposlam/featureeval/FeatureMetrics.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace toposlam::featureeval {

namespace {
double safeDiv(double a, double b, double ifZero) {
    return b > 0 ? a / b : ifZero;
}
}  // namespace

void FeatureScores::add(const features::ScanFeatures& detected, const ScanGroundTruth& truth) {
    const auto& det = detected.corners;
    const auto& gt = truth.corners;
    // Candidate pairs within the radius, nearest first.
    std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < det.size(); ++i) {
        for (std::size_t j = 0; j < gt.size(); ++j) {
            if (gt[j].dontCare)
                continue;
            const double d = std::hypot(det[i].position.x - gt[j].position.x,
                                        det[i].position.y - gt[j].position.y);
            if (d <= matchRadius)
                pairs.emplace_back(d, i, j);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    usedDetection_.assign(det.size(), 0);
    usedTruth_.assign(gt.size(), 0);
    for (const auto& [d, i, j] : pairs) {
        if (usedDetection_[i] || usedTruth_[j])
            continue;
        usedDetection_[i] = usedTruth_[j] = 1;
        ++hits;
        sumSquaredError += d * d;
        if (gt[j].range <= nearRange) {
            ++hitsNear;
            sumSquaredErrorNear += d * d;
        }
        const double angleError = (det[i].angle - gt[j].angle) * 180.0 / M_PI;
        sumSquaredAngleError += angleError * angleError;
        sumAbsAngleError += std::abs(angleError);
    }
    for (const auto& g : gt)
        groundTruthCorners += g.dontCare ? 0 : 1;
    detectedCorners += det.size();
    for (std::size_t i = 0; i < det.size(); ++i) {
        if (usedDetection_[i])
            continue;
        for (const auto& g : gt) {
            if (g.dontCare && std::hypot(det[i].position.x - g.position.x,
                                         det[i].position.y - g.position.y) <= matchRadius) {
                ++ignored;
                break;
            }
        }
    }

    // Segments: greedy one-to-one by beam-span IoU.
    const auto& segs = detected.segments;
    std::vector<std::tuple<double, std::size_t, std::size_t>> overlaps;
    for (std::size_t r = 0; r < truth.runs.size(); ++r) {
        const GroundTruthRun& run = truth.runs[r];
        for (std::size_t s = 0; s < segs.size(); ++s) {
            const double lo = std::max(run.firstBeam, segs[s].firstBeam);
            const double hi = std::min(run.lastBeam, segs[s].lastBeam);
            if (hi < lo)
                continue;
            const double inter = hi - lo + 1;
            const double uni = (run.lastBeam - run.firstBeam + 1.0) +
                               (segs[s].lastBeam - segs[s].firstBeam + 1.0) - inter;
            if (inter / uni >= 0.5)
                overlaps.emplace_back(-inter / uni, r, s);
        }
    }
    std::sort(overlaps.begin(), overlaps.end());
    usedTruth_.assign(truth.runs.size(), 0);
    usedDetection_.assign(segs.size(), 0);
    for (const auto& [negIou, r, s] : overlaps) {
        if (usedTruth_[r] || usedDetection_[s])
            continue;
        usedTruth_[r] = usedDetection_[s] = 1;
        ++matchedRuns;
        const GroundTruthRun& run = truth.runs[r];
        const auto sq = [](const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) {
            return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
        };
        sumSquaredEndpointError += sq(segs[s].start, run.start) + sq(segs[s].end, run.end);
    }
    groundTruthRuns += truth.runs.size();
}

double FeatureScores::precision() const {
    return safeDiv(static_cast<double>(hits), static_cast<double>(detectedCorners - ignored), 1.0);
}
double FeatureScores::recall() const {
    return safeDiv(static_cast<double>(hits), static_cast<double>(groundTruthCorners), 1.0);
}
double FeatureScores::positionRmse() const {
    return std::sqrt(safeDiv(sumSquaredError, static_cast<double>(hits), 0.0));
}
double FeatureScores::positionRmseNear() const {
    return std::sqrt(safeDiv(sumSquaredErrorNear, static_cast<double>(hitsNear), 0.0));
}
double FeatureScores::angleRmseDeg() const {
    return std::sqrt(safeDiv(sumSquaredAngleError, static_cast<double>(hits), 0.0));
}
double FeatureScores::angleMeanAbsDeg() const {
    return safeDiv(sumAbsAngleError, static_cast<double>(hits), 0.0);
}
double FeatureScores::endpointRmse() const {
    return std::sqrt(safeDiv(sumSquaredEndpointError, 2.0 * static_cast<double>(matchedRuns), 0.0));
}
double FeatureScores::segmentRecall() const {
    return safeDiv(static_cast<double>(matchedRuns), static_cast<double>(groundTruthRuns), 1.0);
}

}  // namespace toposlam::featureeval
