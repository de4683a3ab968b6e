#pragma once
// The frame the relation files of Kümmerle et al. (2009) are made in: the laser's. Their
// relations come from laser scans matched by hand, and where a log's laser and odometry
// origins differ they fit the laser (B3: intel's laser sits 0.093 m ahead of its odometry's
// origin, mit-csail's 0.037 m behind, and both logs' relations fit the laser's poses, not the
// odometry's). A SLAM trajectory gives the robot's poses; where a log states its laser off the
// robot's centre (a CARMEN ROBOTLASER line's laser and robot poses, a rawlog scan's
// sensorPose), the poses are moved to the laser before they are scored against such relations.
//
// Only the laser's position counts, not its heading on the robot: a scan's sensor heading also
// carries the centring of its beam layout (intel's 180 readings from -90 to +89 deg put its
// middle 0.5 deg to the right), which is no mounting.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/Trajectory.h>

#include <string>

namespace toposlam::evaluation {

/// One entry per scan of `logPath` (any log io::LaserLogReader reads), in file order: the
/// scan's file stamp and the laser's position on the robot as `pose` (x forward, y left, m;
/// phi 0). Throws io::InputError like the reader.
io::Trajectory2D laserPositionsAtScans(const std::string& logPath,
                                       const io::ProgressCallback& progress = {});

/// The median x and median y of `laserPositions` (m, robot frame); (0, 0) when empty.
mrpt::math::TPoint2D typicalLaserPosition(const io::Trajectory2D& laserPositions);

/// True when some scan's laser sits off the robot's centre (by more than 0.1 mm).
bool laserOffCentre(const io::Trajectory2D& laserPositions);

/// The laser's poses along `robotPoses`: each pose composed with the laser position of the
/// scan with its stamp (within `stampTolerance`, s), or with typicalLaserPosition() where no
/// scan has that stamp. Stamps and headings are kept.
io::Trajectory2D inLaserFrame(const io::Trajectory2D& robotPoses,
                              const io::Trajectory2D& laserPositions, double stampTolerance);

}  // namespace toposlam::evaluation
