#pragma once
// The surface a scan point lies on, as a line through the point's neighbourhood: what
// point-to-line registration pulls other points onto. Fitted by principal axes to the point
// and its neighbours within +-2 beams that are not across a range jump; no line where the
// neighbourhood bends (a corner, a chair leg) or has fewer than 3 points.
#include <toposlam/matching/PolarScan.h>

#include <cstddef>
#include <optional>

namespace toposlam::matching {

/// Line n . p = offset in the scan's SENSOR frame (n unit, m).
struct LocalLine {
    double nx = 0, ny = 0, offset = 0;
};

/// The local line at `beam` of `scan` (which must be valid), or nullopt. Neighbours farther
/// than maxJoinDistance + 3 beam arcs from the previous one are across a jump. The normal
/// points towards the sensor, so offset = n . p < 0: which side of a thin wall was seen.
std::optional<LocalLine> fitLocalLine(const PolarScan& scan, std::size_t beam,
                                      double maxJoinDistance = 0.3);

}  // namespace toposlam::matching
