#pragma once
// SLAM over a whole laser log: read every scan (any format io::LaserLogReader accepts), track
// it with the front end, and produce the trajectory and the occupancy grid.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/io/Trajectory.h>

#include <cstddef>
#include <string>

namespace toposlam::mapping {

struct MappingResult {
    /// Robot pose at every scan: stamp = the scan's fileStamp (as in the log, so relation
    /// files match), pose in the map frame (m, rad): the odometry frame of the first scan,
    /// turned about its origin by wallAlignment.
    io::Trajectory2D trajectory;
    mrpt::maps::COccupancyGridMap2D grid;
    /// Rotation (rad) applied about the map origin to line the walls up with the grid axes
    /// (0 when alignment is off or the walls show no dominant direction).
    double wallAlignment = 0;
    double wallDirectionStrength = 0;  ///< see WallDirection::strength
    std::size_t scans = 0;
    double logDuration = 0;  ///< s, last minus first scan time
    double wallSeconds = 0;  ///< s spent mapping (reading included)
};

/// Runs SLAM on `logPath` with the settings in `ini`: sections [MappingApplication] and
/// [ICP] (icp-slam's keys, see IcpSlam) and [OccupancyGrid] (OccupancyGridOptions, with the
/// alignment of the map to its dominant walls, ManhattanAlignment.h; a bad value there is a
/// config::ConfigError naming the file when `ini` is an mrpt::config::CConfigFile).
/// Shows progress on a terminal. Throws io::InputError for unreadable or malformed logs,
/// and for a log without scans.
MappingResult mapLog(const std::string& logPath, const mrpt::config::CConfigFileBase& ini);

}  // namespace toposlam::mapping
