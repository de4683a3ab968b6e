#pragma once
// Absolute trajectory error (ATE): the estimate's positions, after the rigid 2D transform that
// best aligns them with the ground-truth positions at the same stamps (RigidAlignment2D.h),
// compared with the ground truth point by point. Unlike the relation metric it measures global
// consistency (a bent corridor costs at every pose after the bend), so it complements it.
#include <mrpt/math/TPose2D.h>
#include <toposlam/evaluation/ErrorStatistics.h>
#include <toposlam/evaluation/StampedPoseLookup.h>
#include <toposlam/io/Trajectory.h>

#include <cstddef>

namespace toposlam::evaluation {

struct AbsoluteTrajectoryErrorResult {
    std::size_t estimatePoses = 0;
    /// Estimate poses with a ground-truth pose at the same stamp (within the tolerance); only
    /// these are aligned and scored.
    std::size_t matchedPoses = 0;
    /// The alignment applied to the estimate (estimate frame -> ground-truth frame).
    mrpt::math::TPose2D alignment;
    ErrorStatistics position;  ///< |aligned position - true position|, m (rms = ATE RMSE)
    ErrorStatistics heading;   ///< |aligned yaw - true yaw| wrapped, degrees
};

/// Throws std::invalid_argument for non-finite poses in either trajectory.
AbsoluteTrajectoryErrorResult evaluateAbsoluteTrajectoryError(
    const io::Trajectory2D& estimate, const io::Trajectory2D& groundTruth,
    double stampTolerance = StampedPoseLookup::kDefaultTolerance);

}  // namespace toposlam::evaluation
