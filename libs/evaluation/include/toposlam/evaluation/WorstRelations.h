#pragma once
// The relations a method got most wrong, with what the reference and the method each say the
// motion was, and how every other method scored on the same relation: where to look first in
// a trajectory, and a way to tell a method's failure (the others agree with the reference)
// from a doubtful reference relation (every method disagrees with it alike).
#include <mrpt/math/TPose2D.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct SlamEvaluation;

/// One of a method's worst relations.
struct WorstRelation {
    std::size_t relation = 0;       ///< index in the relation list
    double stamp1 = 0, stamp2 = 0;  ///< s
    /// δ_gt: the reference's pose at stamp2 in the frame of the pose at stamp1 (m, rad).
    mrpt::math::TPose2D reference;
    /// δ_est = δ_gt ⊕ e: the method's motion over the same relation (m, rad).
    mrpt::math::TPose2D estimate;
    double translation = 0;  ///< |trans(e)|, m
    double rotationDeg = 0;  ///< |e.phi|, degrees
};

/// The `count` matched relations of `result` with the largest translational error, largest
/// first (equal errors: in relation order). `relations` is the list `result` was scored on.
std::vector<WorstRelation> worstRelations(const RelativePoseErrorResult& result,
                                          const PoseRelations& relations, std::size_t count);

/// One Markdown table per method that has worst relations (MethodEvaluation::worst): stamps,
/// reference and estimated motion, the error, and each other method's translational error on
/// that relation ("–" where it did not match it). Empty when no method has any.
std::string formatWorstRelations(const SlamEvaluation& evaluation);

}  // namespace toposlam::evaluation
