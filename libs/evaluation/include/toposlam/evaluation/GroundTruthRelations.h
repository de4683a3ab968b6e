#pragma once
// A relation set derived from a ground-truth trajectory, so that logs with a true trajectory
// (TopoSLAM's simulated logs, MRPT's simul.rawlog) are scored with the same relation metric
// as the Kümmerle et al. benchmark logs (see RelativePoseError.h).
//
// Scheme (every relation goes from an earlier to a later pose, in trajectory order):
//  1. local: every pair of consecutive poses (i, i+1). This is the motion between two scans,
//     what scan matching and odometry must get right.
//  2. multi-scale: for separations d = d0, 2·d0, 4·d0, ... (d0 = baseSeparation, up to the
//     path length of the whole trajectory), relations (i, j) where j is the first pose at
//     least d metres of travelled path after i, with the start poses i spaced d/2 metres of
//     path apart (the first is pose 0). So every stretch of the path is covered about twice
//     at every scale, and each scale contributes about 2·L/d relations (L = path length):
//     the drift over 1 m, 2 m, 4 m ... of travel, the longest ones spanning loops.
// The doubling ladder weighs all scales of drift alike without letting long relations
// dominate the count; it follows the segment-length idea of the KITTI odometry metric.
// Path length is the sum of the Euclidean steps between consecutive poses, so turning in place
// adds nothing to it (the local relations measure those rotations).
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/io/Trajectory.h>

#include <vector>

namespace toposlam::evaluation {

struct GroundTruthRelationOptions {
    /// Include the relations between consecutive poses (step 1).
    bool consecutive = true;
    /// d0: shortest multi-scale separation, m of travelled path; <= 0 disables step 2.
    double baseSeparation = 1.0;
};

/// Relations of `groundTruth` under the scheme above, local ones first, then by scale and
/// start pose. Stamps are those of the trajectory's poses. `separations`, if given, receives
/// the scale of each relation: 0 for consecutive pairs, d (m) for the multi-scale ones.
/// Throws std::invalid_argument for a non-finite pose.
PoseRelations relationsFromGroundTruth(const io::Trajectory2D& groundTruth,
                                       const GroundTruthRelationOptions& options = {},
                                       std::vector<double>* separations = nullptr);

}  // namespace toposlam::evaluation
