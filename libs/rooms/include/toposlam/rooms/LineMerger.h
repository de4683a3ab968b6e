#pragma once
// Step 2b of the virtual-door method (sec. 1.4.2, eqs. 5-7): segments that belong to the same
// wall but came out of the Hough transform as several overlapping pieces are merged, so that
// the main-direction voter counts each wall once. Two segments merge when
//   direction: the angle between them is below maxAngle (eq. 5),
//   distance:  the mean distance of one's endpoints to the other's line is below maxDistance
//              (eq. 6),
//   overlap:   their midpoints are closer than half the sum of their lengths (eq. 7).
// The longer segment is the base (line 1 in fig. 3): the other's endpoints are projected on it
// and the base is extended to cover them. Repeated until no pair merges.
#include <toposlam/rooms/LineSegment.h>

#include <vector>

namespace toposlam::rooms {

class LineMerger {
  public:
    struct Options {
        double maxAngleDeg = 5.0;  ///< delta_phi (deg)
        double maxDistance = 0.1;  ///< delta_d (m)
    };

    LineMerger() = default;
    explicit LineMerger(const Options& options) : options_(options) {}

    /// `resolution`: m per pixel, to express maxDistance in pixels.
    std::vector<LineSegment> merge(std::vector<LineSegment> lines, double resolution) const;

    /// The three constraints of eqs. 5-7 for `candidate` against `base` (pixels, radians).
    static bool canMerge(const LineSegment& base, const LineSegment& candidate, double maxAngleRad,
                         double maxDistancePx);

  private:
    Options options_;
};

}  // namespace toposlam::rooms
