#pragma once
// The one search the segment graph cannot do: where every matched segment is (nearly)
// parallel, as in a corridor, the lines fix the rotation and the position across them but
// nothing along them, and the segments' midpoints or ends are no help (each scan sees a
// different stretch of the walls). What fixes that position is whatever else the scans share
// (door frames, pillars, clutter, the corridor's end). This search slides the pose along the
// free direction and keeps the offset that the most current points confirm against the
// reference scan (AlignmentScorer: inliers minus free-space violations), coarse to fine.
// The scorer's inlier distance (0.1 m) makes every shared structure a +-0.1 m peak, so the
// coarse step must stay below twice that.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/PolarScan.h>

namespace toposlam::matching {

struct AlongLineSearchOptions {
    double range = 6.0;        ///< m, searched on each side of the starting pose
    double coarseStep = 0.15;  ///< m
    double fineStep = 0.03;    ///< m, around the best coarse offset
    std::size_t stride = 3;    ///< score every stride-th current beam
};

/// Best pose among pose + s * direction (direction: unit vector in the reference frame),
/// |s| <= options.range; `pose` itself when nothing scores better.
mrpt::poses::CPose2D searchAlongLine(const PolarScan& reference, const PolarScan& current,
                                     const mrpt::poses::CPose2D& pose,
                                     const mrpt::math::TPoint2D& direction,
                                     const AlongLineSearchOptions& options,
                                     const AlignmentScoreOptions& score);

}  // namespace toposlam::matching
