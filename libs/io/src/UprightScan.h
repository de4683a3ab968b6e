#pragma once
// A 2D laser mounted upside down (rolled or pitched by 180 deg, as robots often carry a
// Hokuyo) sweeps its plane the other way round. MRPT states that in the scan's 3D
// sensorPose; 2D code that reads the pose as CPose2D(x, y, yaw) would mirror every scan.
#include <mrpt/obs/CObservation2DRangeScan.h>

namespace toposlam::io {

/// Rewrites a scan whose laser looks down its plane's normal (an upside-down mount, within
/// 5 deg) as the same readings from an upright laser: the sweep direction reversed
/// (rightToLeft) and the sensor pose level, its yaw the direction the first reading's
/// mirror image points at. Every reading keeps its point in the robot frame. Returns
/// whether the scan was rewritten.
bool makeUpright(mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace toposlam::io
