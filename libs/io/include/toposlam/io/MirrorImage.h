#pragma once
// The mirror image of a log: the same robot, laser and odometry driving through the mirror
// image of its building (left and right swapped, the reflection y -> -y of every frame). A
// log and its mirror image are equally hard to map, so a SLAM method that scores differently
// on them depends on which way the robot turns or on which side the clutter stands, not on
// the data's difficulty (toposlam-convert --mirror, toposlam-bench-slam --mirror).
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/io/Trajectory.h>

namespace toposlam::io {

/// A pose, or a motion between two poses, in the mirror image: (x, -y, -yaw) (m, rad).
mrpt::math::TPose2D mirroredPose(const mrpt::math::TPose2D& pose);
mrpt::poses::CPose2D mirroredPose(const mrpt::poses::CPose2D& pose);

/// Every pose of `trajectory` in the mirror image, stamps kept.
Trajectory2D mirroredTrajectory(const Trajectory2D& trajectory);

/// `scan` as its laser would have read the mirror image of the scene: the point of every
/// reading in the robot frame, (x, y, z), becomes (x, -y, z). The readings (and their
/// validity and intensities) are reversed, so that reading i looks where reading n-1-i
/// looked, mirrored (MRPT's beams are symmetric about the sensor's x axis), and the sensor
/// pose is mirrored: y, yaw and roll negated. Everything else is kept.
mrpt::obs::CObservation2DRangeScan::Ptr mirroredScan(
    const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace toposlam::io
