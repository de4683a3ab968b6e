#pragma once
// Which frame on the robot a relation file was made in, as far as a trajectory can tell: the
// point d m ahead of each estimated pose (along its heading) whose motions fit the reference
// motions best, by the mean translational error of the relation metric (RelativePoseError.h).
// A trajectory of the laser's poses scored against relations of the robot's centre (or the
// reverse) is off by the mounting, and the error it adds grows with the turn of each relation
// (2·d·sin(θ/2)); fitting d finds it, and toposlam-eval-slam --frame-offset d scores there.
// The search scans [-maxOffset, maxOffset] in 1 cm steps, then the 2 cm around the best of
// them in 0.1 mm steps: a plain scan, since the mean error need not be convex in d far from its
// minimum (300 evaluations of the metric; fr079's 1685 relations take a few milliseconds).
#include <mrpt/math/TPose2D.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>
#include <toposlam/io/Trajectory.h>

namespace toposlam::evaluation {

struct FrameOffsetFit {
    double offset = 0;         ///< m ahead of the poses scored (negative: behind)
    double meanError = 0;      ///< m, mean translational error there
    double meanErrorAsIs = 0;  ///< m, the same at offset 0 (the poses as scored)
    double gain() const { return meanErrorAsIs - meanError; }  ///< m, >= 0
};

/// `pose` moved `d` m along its heading (m, rad): the frame d m ahead of it (negative: behind).
/// What --frame-offset scores and what the fit below tries.
mrpt::math::TPose2D poseAhead(const mrpt::math::TPose2D& pose, double d);

/// The best offset for `estimate` against `relations`, over the relations `scored` matched
/// (evaluateRelativePoseError of the same estimate and relations). All zero when it matched
/// none.
FrameOffsetFit fitFrameOffset(const io::Trajectory2D& estimate, const PoseRelations& relations,
                              const RelativePoseErrorResult& scored, double maxOffset = 0.5);

}  // namespace toposlam::evaluation
