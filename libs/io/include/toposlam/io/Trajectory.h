#pragma once
// Robot trajectories as text, one pose per line: "timestamp x y yaw"
// (timestamp in seconds, x y in metres, yaw in radians; the map/world frame of whoever wrote
// it). '#' starts a comment line. This is the format every TopoSLAM app reads and writes.
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace toposlam::io {

struct TimedPose2D {
    double stamp = 0;             ///< s
    mrpt::math::TPose2D pose;     ///< x, y (m), phi (rad)
};
using Trajectory2D = std::vector<TimedPose2D>;

/// Throws InputError naming the file and line for malformed lines or non-finite values.
Trajectory2D loadTrajectory(const std::string& path);
/// Atomic write with full double precision.
void saveTrajectory(const Trajectory2D& trajectory, const std::string& path);

}  // namespace toposlam::io
