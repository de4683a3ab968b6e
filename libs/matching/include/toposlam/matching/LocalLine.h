#pragma once
// The surface a scan point lies on, as a line through the point's neighbourhood: what
// point-to-line registration pulls other points onto. Fitted by principal axes to the point
// and its neighbours on either side that are not across a range jump; no line where the
// neighbourhood bends (a corner, a chair leg) or has fewer than 3 points.
// How far the neighbourhood reaches follows the scan's own noise. Two beams either side span
// 2-5 cm on a wall 1.5 m from a Hokuyo URG-04LX (0.35 deg per beam); with its 2 cm range noise
// the straightness test throws out 9 readings in 10 and the normals it keeps are 25 deg RMS
// off (a simulated 4 x 4 m room, test_local_line.cpp). They give a corridor a pull along
// itself that no wall in it has: ICP then claims to know the position along the corridor to
// millimetres and is wrong by centimetres. A line needs about 16 times the noise along it
// before noise alone cannot bend it past the straightness test, so the neighbourhood reaches
// 8 times the scan's noise on each side (localLineReach), at least 2 beams, at most 16.
#include <toposlam/matching/PolarScan.h>

#include <cmath>
#include <cstddef>
#include <optional>

namespace toposlam::matching {

/// Line n . p = offset in the scan's SENSOR frame (n unit, m).
struct LocalLine {
    double nx = 0, ny = 0, offset = 0;
};

/// Two neighbouring readings of `scan` at about `range` (m) farther apart than this (m) lie
/// across a range jump, not on one surface: maxJoinDistance plus 3 beam arcs.
inline double jumpGap(const PolarScan& scan, double range, double maxJoinDistance) {
    return maxJoinDistance + 3 * std::abs(scan.bearingStep()) * range;
}

/// Robust standard deviation (m) of the scan's readings across the surfaces they lie on: the
/// median distance of every reading from the chord of its two neighbours (none across a range
/// jump of maxJoinDistance + 3 beam arcs), scaled to a Gaussian's sigma. Corners and edges are
/// a minority and do not move the median. 0 when fewer than 10 readings have two neighbours.
double surfaceNoise(const PolarScan& scan, double maxJoinDistance = 0.3);

/// How far (m) fitLocalLine's neighbourhood reaches on each side for a scan with this
/// surfaceNoise: 8 sigma.
double localLineReach(double noise);

/// The local line at `beam` of `scan` (which must be valid), or nullopt. Neighbours are taken
/// on each side until one lies `reach` (m) from the reading (at least 2 beams, at most 16);
/// reach 0 gives +-2 beams. Neighbours farther than maxJoinDistance + 3 beam arcs from the
/// previous one are across a jump. The normal points towards the sensor, so offset = n . p < 0:
/// which side of a thin wall was seen.
std::optional<LocalLine> fitLocalLine(const PolarScan& scan, std::size_t beam,
                                      double maxJoinDistance = 0.3, double reach = 0);

}  // namespace toposlam::matching
