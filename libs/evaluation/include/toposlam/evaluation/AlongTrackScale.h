#pragma once
// Whether a trajectory's motion reads long or short along the direction of travel, over the
// relations of the metric (RelativePoseError.h). For a relation with true motion δ_gt
// (translation t_gt) and estimated translation t_est (both in the frame of its first pose),
// the along-track error is (t_est − t_gt) · t_gt / |t_gt|; summed over the relations and
// divided by the sum of |t_gt| it is the estimate's scale error: −1 % when the robot is placed
// 1 cm short on every metre it drove. The mean translational error cannot tell that bias from
// noise; a front end that slides back in corridors, or an odometry that reads long, shows
// here with its sign. Only the relations of one stretch of driving count: their poses at
// most kAlongTrackMaxSeconds apart (not a place revisited minutes later, where the estimate's
// drift, not its scale, sets the error), moving at least a minimum (on a turn on the spot the
// direction of travel is noise) and at most a maximum (over long stretches a drifted heading
// shortens the displacement too, a bent path's chord). So this is the local scale.
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <cstddef>

namespace toposlam::evaluation {

struct AlongTrackScale {
    std::size_t relations = 0;  ///< matched relations of one stretch of driving (above)
    double pathLength = 0;      ///< m, sum of their |t_gt|
    double error = 0;           ///< m, sum of their along-track errors (negative: short)
    /// error / pathLength in per cent; 0 when no relation moved enough.
    double percent() const { return pathLength > 0 ? 100.0 * error / pathLength : 0.0; }
};

/// alongTrackScale's relations: true travel |t_gt| in [kAlongTrackMinLength,
/// kAlongTrackMaxLength] m, stamps at most kAlongTrackMaxSeconds apart.
inline constexpr double kAlongTrackMinLength = 0.05;
inline constexpr double kAlongTrackMaxLength = 2.0;
inline constexpr double kAlongTrackMaxSeconds = 10.0;

/// The along-track scale of the relations `scored` matched (evaluateRelativePoseError against
/// the same `relations`) that belong to one stretch of driving (the three limits above).
AlongTrackScale alongTrackScale(const PoseRelations& relations,
                                const RelativePoseErrorResult& scored);

}  // namespace toposlam::evaluation
