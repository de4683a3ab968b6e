#include <toposlam/evaluation/GroundTruthRelations.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace toposlam::evaluation {

namespace {

PoseRelation relationBetween(const io::TimedPose2D& from, const io::TimedPose2D& to) {
    return {from.stamp, to.stamp, to.pose - from.pose};  // from⁻¹ ⊕ to
}

}  // namespace

PoseRelations relationsFromGroundTruth(const io::Trajectory2D& groundTruth,
                                       const GroundTruthRelationOptions& options,
                                       std::vector<double>* separations) {
    const std::size_t n = groundTruth.size();
    // pathLength[i]: metres travelled from pose 0 to pose i.
    std::vector<double> pathLength(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = groundTruth[i];
        if (!std::isfinite(p.stamp) || !std::isfinite(p.pose.x) || !std::isfinite(p.pose.y) ||
            !std::isfinite(p.pose.phi)) {
            throw std::invalid_argument("ground-truth pose " + std::to_string(i) +
                                        " is not finite");
        }
        if (i > 0) {
            const auto& q = groundTruth[i - 1].pose;
            pathLength[i] = pathLength[i - 1] + std::hypot(p.pose.x - q.x, p.pose.y - q.y);
        }
    }

    PoseRelations relations;
    if (options.consecutive) {
        for (std::size_t i = 0; i + 1 < n; ++i) {
            relations.push_back(relationBetween(groundTruth[i], groundTruth[i + 1]));
        }
    }
    if (separations)
        separations->assign(relations.size(), 0.0);
    if (n < 2 || !(options.baseSeparation > 0))
        return relations;

    const double total = pathLength.back();
    // First pose at least `distance` metres of path after pose i (end() when none).
    auto firstAtDistance = [&](std::size_t i, double distance) {
        return std::lower_bound(pathLength.begin() + static_cast<std::ptrdiff_t>(i),
                                pathLength.end(), pathLength[i] + distance);
    };
    for (double d = options.baseSeparation; d <= total; d *= 2) {
        for (std::size_t start = 0;;) {
            const auto end = firstAtDistance(start, d);
            if (end == pathLength.end())
                break;
            const auto j = static_cast<std::size_t>(end - pathLength.begin());
            relations.push_back(relationBetween(groundTruth[start], groundTruth[j]));
            if (separations)
                separations->push_back(d);
            // Next start: d/2 further along the path, and at least one pose further.
            const auto next = firstAtDistance(start, d / 2);
            start = std::max(start + 1, static_cast<std::size_t>(next - pathLength.begin()));
            if (start >= n)
                break;
        }
    }
    return relations;
}

}  // namespace toposlam::evaluation
