#pragma once
// Robot trajectories as text, one pose per line: "timestamp x y yaw"
// (timestamp in seconds, x y in metres, yaw in radians; the map/world frame of whoever wrote
// it). Fields are separated by blanks; '#' starts a comment line; blank lines are ignored.
// This is the format every TopoSLAM app reads and writes (share/doc/file-formats.md).
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace toposlam::io {

struct TimedPose2D {
    double stamp = 0;          ///< s
    mrpt::math::TPose2D pose;  ///< x, y (m), phi (rad)
};
using Trajectory2D = std::vector<TimedPose2D>;

/// Throws InputError naming the file and line for a missing file, a line without exactly 4
/// numeric fields, or non-finite values.
Trajectory2D loadTrajectory(const std::string& path);
/// Atomic write. Every number is printed in the shortest form that reads back to the same
/// double, so save/load round-trips exactly and CARMEN stamps keep their printed digits;
/// stamps without an exponent (1700000000, not 1.7e+09).
/// Starts with a "# timestamp x y yaw" comment line.
void saveTrajectory(const Trajectory2D& trajectory, const std::string& path);

}  // namespace toposlam::io
