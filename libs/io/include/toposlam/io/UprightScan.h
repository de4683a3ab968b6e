#pragma once
// A 2D laser mounted upside down (rolled or pitched by 180 deg, as robots often carry a
// Hokuyo) sweeps its plane the other way round. MRPT states that in the scan's 3D
// sensorPose; 2D code that reads the pose as CPose2D(x, y, yaw) would mirror every scan.
// LaserLogReader returns such scans upright; MRPT-facing classes fed by MRPT's own tools
// (CGraphSlamBuilder, CScanFeaturesMap) turn them upright themselves.
#include <mrpt/obs/CObservation2DRangeScan.h>

namespace toposlam::io {

/// Whether the scan's laser looks down its plane's normal (an upside-down mount, within
/// 5 deg).
bool isUpsideDown(const mrpt::obs::CObservation2DRangeScan& scan);

/// Rewrites a scan whose laser looks down its plane's normal (an upside-down mount, within
/// 5 deg) as the same readings from an upright laser: the sweep direction reversed
/// (rightToLeft) and the sensor pose level, its yaw the direction the first reading's
/// mirror image points at. Every reading keeps its point in the robot frame. Returns
/// whether the scan was rewritten.
bool makeUpright(mrpt::obs::CObservation2DRangeScan& scan);

/// `scan` itself when it is upright, else an upright copy (makeUpright): for code handed
/// scans it must not change.
mrpt::obs::CObservation2DRangeScan::Ptr uprightScan(
    const mrpt::obs::CObservation2DRangeScan::Ptr& scan);

}  // namespace toposlam::io
