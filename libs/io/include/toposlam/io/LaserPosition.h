#pragma once
// Where a laser sits on the robot (robot frame: x forward, y left, m), as the logs state it
// (a CARMEN ROBOTLASER line's laser and robot poses, a rawlog scan's sensorPose). One wording
// and one threshold for every report that names it: toposlam-slam's summary and the SLAM
// benchmark's log lines.
#include <mrpt/math/TPoint2D.h>

#include <string>

namespace toposlam::io {

/// True when the laser sits farther than 0.1 mm from the robot's centre: a log that states
/// its laser's mount to the millimetre and puts it at the centre is centred.
bool laserOffCentre(const mrpt::math::TPoint2D& laser);

/// "0.220 m ahead and 0.000 m left of the robot's centre" (behind / right for negative x / y;
/// millimetres).
std::string describeLaserPosition(const mrpt::math::TPoint2D& laser);

}  // namespace toposlam::io
