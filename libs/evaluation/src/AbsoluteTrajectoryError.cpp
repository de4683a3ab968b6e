#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/RigidAlignment2D.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace toposlam::evaluation {

namespace {

void requireFinite(const io::Trajectory2D& t, const char* what) {
    for (std::size_t i = 0; i < t.size(); ++i) {
        const auto& p = t[i];
        if (!std::isfinite(p.stamp) || !std::isfinite(p.pose.x) || !std::isfinite(p.pose.y) ||
            !std::isfinite(p.pose.phi)) {
            throw std::invalid_argument(std::string(what) + " pose " + std::to_string(i) +
                                        " is not finite");
        }
    }
}

}  // namespace

AbsoluteTrajectoryErrorResult evaluateAbsoluteTrajectoryError(const io::Trajectory2D& estimate,
                                                              const io::Trajectory2D& groundTruth,
                                                              double stampTolerance) {
    requireFinite(estimate, "trajectory");
    requireFinite(groundTruth, "ground-truth");
    const StampedPoseLookup truthAt(groundTruth, stampTolerance);

    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (estimate, ground truth)
    std::vector<mrpt::math::TPoint2D> estimated, truth;
    for (std::size_t i = 0; i < estimate.size(); ++i) {
        if (const auto g = truthAt.find(estimate[i].stamp)) {
            pairs.emplace_back(i, *g);
            estimated.push_back(estimate[i].pose.translation());
            truth.push_back(groundTruth[*g].pose.translation());
        }
    }

    AbsoluteTrajectoryErrorResult result;
    result.estimatePoses = estimate.size();
    result.matchedPoses = pairs.size();
    result.alignment = alignRigid2D(estimated, truth);

    std::vector<double> position, heading;
    for (const auto& [e, g] : pairs) {
        const mrpt::math::TPose2D aligned = result.alignment + estimate[e].pose;
        const auto& t = groundTruth[g].pose;
        position.push_back(std::hypot(aligned.x - t.x, aligned.y - t.y));
        heading.push_back(mrpt::RAD2DEG(std::abs(mrpt::math::wrapToPi(aligned.phi - t.phi))));
    }
    result.position = summarizeErrors(position);
    result.heading = summarizeErrors(heading);
    return result;
}

}  // namespace toposlam::evaluation
