#pragma once
// The relation-based SLAM accuracy metric of Kümmerle et al. 2009 ("On measuring the accuracy
// of SLAM algorithms", Autonomous Robots 27(4)), the B3 metric of TopoSLAM's benchmarks.
//
// For every ground-truth relation (t1, t2, δ_gt) the estimated motion is
//     δ_est = x_t1⁻¹ ⊕ x_t2                      (x_t: estimated pose at stamp t)
// and its error is
//     e = δ_est ⊖ δ_gt = δ_gt⁻¹ ⊕ δ_est.
// The translational error is |(e.x, e.y)| (m), the rotational error |e.phi| wrapped to [0, π]
// (reported in degrees). Note |trans(e)| = |t_est − t_gt|: it does not depend on the
// rotational error. Cartographer composes the other way round (δ_est ⊕ δ_gt⁻¹, whose
// translation mixes in the rotational error times |t_gt|), which gives slightly larger
// translational errors; this is NOT what this file computes.
//
// The metric is invariant to where the trajectory is in the world: any rigid transform of the
// whole estimate leaves every δ_est unchanged.
#include <mrpt/math/TPose2D.h>
#include <toposlam/evaluation/ErrorStatistics.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/StampedPoseLookup.h>
#include <toposlam/io/Trajectory.h>

#include <cstddef>
#include <vector>

namespace toposlam::evaluation {

/// e = δ_gt⁻¹ ⊕ (from⁻¹ ⊕ to): the error of the estimated motion from pose `from` to pose `to`
/// against the true motion `trueMotion` (m, rad; phi of the result wrapped to (-π, π]).
mrpt::math::TPose2D relativePoseError(const mrpt::math::TPose2D& from,
                                      const mrpt::math::TPose2D& to,
                                      const mrpt::math::TPose2D& trueMotion);

struct RelativePoseErrorOptions {
    /// Largest |stamp difference| (s) at which a relation stamp matches a trajectory pose.
    double stampTolerance = StampedPoseLookup::kDefaultTolerance;
};

/// The error of one matched relation.
struct RelationError {
    std::size_t relation = 0;   ///< index in the relation list
    std::size_t fromPose = 0;   ///< index in the trajectory of the pose at stamp1
    std::size_t toPose = 0;     ///< index in the trajectory of the pose at stamp2
    mrpt::math::TPose2D error;  ///< e (m, rad)
    double translation = 0;     ///< |(e.x, e.y)|, m
    double rotationDeg = 0;     ///< |e.phi|, degrees
};

struct RelativePoseErrorResult {
    std::size_t totalRelations = 0;
    /// Relations whose two stamps both have a pose in the trajectory; the others are left out
    /// of every statistic (count them: a trajectory that misses scans looks better than it is).
    std::size_t matchedRelations = 0;
    std::vector<RelationError> errors;   ///< one per matched relation, in relation order
    ErrorStatistics translation;         ///< m
    ErrorStatistics rotation;            ///< degrees
    ErrorStatistics translationSquared;  ///< m²
    ErrorStatistics rotationSquared;     ///< deg²
    std::size_t unmatchedRelations() const { return totalRelations - matchedRelations; }
};

/// Scores `estimate` against `relations`. Throws std::invalid_argument when a pose of the
/// estimate is not finite (a NaN would silently poison every statistic).
RelativePoseErrorResult evaluateRelativePoseError(const io::Trajectory2D& estimate,
                                                  const PoseRelations& relations,
                                                  const RelativePoseErrorOptions& options = {});

}  // namespace toposlam::evaluation
