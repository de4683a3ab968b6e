#pragma once
// The one search the segment graph cannot do: where every matched segment is (nearly)
// parallel, as in a corridor, the lines fix the rotation and the position across them but
// nothing along them, and the segments' midpoints or ends are no help (each scan sees a
// different stretch of the walls). What fixes that position is whatever else the scans share
// (door frames, pillars, clutter, the corridor's end).
// This search finds the offset s along the free direction u by 1D voting: with the pose's
// rotation and position across u fixed, every pair of a current point p and a reference
// point q that lie at the same position across u (within acrossTolerance) votes for the
// offset s = (q - (R p + t)) . u that would bring p onto q. Points on the parallel walls vote
// for every offset alike; shared structures across the walls make the peaks. The strongest
// peaks are then checked with the AlignmentScorer at a few offsets around each, against the
// starting pose: the pose moves only if more points confirm it.
// O((n/stride)^2) per search, far cheaper than scoring every offset.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/PolarScan.h>

#include <cstdint>
#include <vector>

namespace toposlam::matching {

struct AlongLineSearchOptions {
    double range = 6.0;             ///< m, searched on each side of the starting pose
    double bin = 0.05;              ///< m, vote bin
    double acrossTolerance = 0.08;  ///< m
    std::size_t stride = 2;         ///< use every stride-th beam of both scans
    double fineStep = 0.03;         ///< m, scorer check around each peak (+-1 step)
    std::size_t peaks = 3;          ///< vote peaks checked with the scorer

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

class AlongLineSearch {
  public:
    /// Best pose among pose + s * direction (direction: unit vector in the reference frame),
    /// |s| <= options.range; `pose` itself when nothing scores better.
    mrpt::poses::CPose2D search(const PolarScan& reference, const PolarScan& current,
                                const mrpt::poses::CPose2D& pose,
                                const mrpt::math::TPoint2D& direction,
                                const AlongLineSearchOptions& options,
                                const AlignmentScoreOptions& score);

  private:
    std::vector<std::uint32_t> votes_, sums_;
    std::vector<mrpt::math::TPoint2D> ref_;
};

}  // namespace toposlam::matching
