#pragma once
// Closed-form rigid 2D transforms from correspondences. A transform T = (x, y, phi) maps a
// point of the CURRENT scan's frame into the REFERENCE scan's frame: p_ref = R(phi) p_cur + t,
// so T is the pose of the current sensor in the reference sensor's frame (MRPT: the pose of
// map m2 relative to map m1).
//  - fromPoints: weighted least squares over point pairs (2D Umeyama / Horn), exact for
//    noise-free pairs. The paper builds its transform from segment midpoints this way.
//  - fromLines: from segment pairs read as infinite lines. Midpoints of partly occluded
//    segments are biased (the visible part of a wall differs between scans), but a segment's
//    direction and its line's normal offset are not: phi is the weighted circular mean of
//    the heading differences, t the least-squares solution of n_ref . (R c_cur + t) =
//    n_ref . c_ref over the pairs (c: any point of the segment, n: the reference normal).
//    Lines only fix t across their own direction; when all of them are (nearly) parallel,
//    the along-line component comes from the midpoints through a weak regulariser and the
//    estimate is reported as degenerate.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace toposlam::matching {

struct PointPair {
    mrpt::math::TPoint2D current, reference;  ///< m, each in its own scan's frame
    double weight = 1;
};

/// A segment of the current scan and its counterpart in the reference scan, each given by a
/// point on it (its midpoint) and its unit direction (first beam -> last beam).
struct LinePair {
    mrpt::math::TPoint2D currentPoint, currentDirection;
    mrpt::math::TPoint2D referencePoint, referenceDirection;
    double weight = 1;  ///< e.g. the shorter segment's length
};

struct TransformEstimate {
    mrpt::poses::CPose2D pose;
    bool valid = false;  ///< false when there is no data (or all weights are 0)
    /// Smallest / largest eigenvalue of the translation's normal matrix: ~0 when the data
    /// fix the translation in one direction only (parallel lines, coincident points).
    double conditioning = 0;
    /// Unit direction (reference frame) the data fix worst: for parallel lines, along them.
    mrpt::math::TPoint2D weakDirection{1, 0};
};

TransformEstimate rigidTransformFromPoints(const std::vector<PointPair>& pairs);
TransformEstimate rigidTransformFromLines(const std::vector<LinePair>& pairs);

}  // namespace toposlam::matching
