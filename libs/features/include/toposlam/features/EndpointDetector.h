#pragma once
// Graph-matching paper, sec. 2.1: convex and concave endpoints. A reading whose windowed turn
// (TurningAngle.h) is below -threshold (-pi/3) is convex (a corner of an obstacle, bulging
// towards the sensor), above +threshold concave (a room corner). Noise makes several
// neighbouring readings pass: non-maximum suppression keeps, of each stretch of consecutive
// readings passing with the same sign, the one with the largest |turn|.
// Jump points (JumpDetector.h) are convex endpoints too: the nearer reading of each jump.
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/features/ScanPoints.h>
#include <toposlam/features/TurningAngle.h>

#include <vector>

namespace toposlam::features {

/// Appends to `out` (cleared first), in canonical order: Convex and Concave endpoints from
/// the turns, Jump endpoints from the run ends; beam = canonical index, position = the point
/// of `pts` at it.
void detectEndpoints(const ScanPoints& pts, const std::vector<PointRun>& runs,
                     const TurningAngle& turning, double threshold, std::vector<Endpoint>& out);

}  // namespace toposlam::features
