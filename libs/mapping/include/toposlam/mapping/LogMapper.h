#pragma once
// SLAM over a whole laser log: read every scan (any format io::LaserLogReader accepts), run
// the configured engine, and produce the trajectory, the occupancy grid and, for the graph
// engine, the keyframe graph and keyframes.
//   engine = graph  TopoSLAM's graph SLAM (GraphSlamInput: our features, point-to-line
//                   registration, graph matcher, loop closure, pose-graph optimisation)
//   engine = icp    MRPT's CMetricMapBuilderICP, the engine of icp-slam (IcpEngine.h, loaded
//                   only for it), kept as the comparison row
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/config/Options.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/mapping/PoseGraph.h>
#include <toposlam/mapping/SlamStatistics.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace toposlam::mapping {

/// Section [Slam] of config_ini/toposlam-slam.ini: which SLAM engine maps the log.
struct SlamEngineOptions : public config::Options {
    /// "graph": TopoSLAM's graph SLAM (GraphSlamInput); "icp": MRPT's ICP map builder,
    /// the engine of icp-slam (IcpEngine.h), kept as the comparison row of B3.
    std::string engine = "graph";
    /// The laser to map with, by sensor label (CARMEN: FLASER, RLASER, ROBOTLASER1, ...).
    /// "auto": the log's only laser, or when it has several its front laser (CARMEN) or the
    /// first scan's (rawlog); the scans of the others are left out and counted in the summary.
    std::string scanLabel = "auto";
    void declare(config::OptionsSchema& s) override;
};

struct MappingResult {
    std::string engine;  ///< "graph" or "icp"
    /// Robot pose at every scan: stamp = the scan's fileStamp (as in the log, so relation
    /// files match), pose in the map frame (m, rad): the robot frame at the first scan,
    /// turned about its origin by wallAlignment.
    io::Trajectory2D trajectory;
    mrpt::maps::COccupancyGridMap2D grid;
    /// Rotation (rad) applied about the map origin to line the walls up with the grid axes
    /// (0 when alignment is off or the walls show no dominant direction).
    double wallAlignment = 0;
    double wallDirectionStrength = 0;  ///< see WallDirection::strength
    std::size_t scans = 0;
    std::string laserLabel;  ///< the sensor label of the scans mapped
    /// Where the first scan puts the laser on the robot (m, x forward, y left): the trajectory
    /// gives the robot's poses, which are this far from the laser's.
    mrpt::math::TPoint2D laserPosition{0, 0};
    /// Scans of other lasers in the log, left out (by sensor label); empty for a one-laser log.
    std::map<std::string, std::size_t> otherLaserScans;
    double logDuration = 0;  ///< s, last minus first scan time
    double wallSeconds = 0;  ///< s spent mapping (reading and the grid included)
    double cpuSeconds = 0;   ///< CPU time of the process spent on it (s)
    // Graph engine only (map frame, like the trajectory):
    std::optional<SlamStatistics> statistics;
    /// Which loop rules ran: guess-free search (global_search_every > 0), accepting agreeing
    /// matches beyond the gate (loop_contested_support > 0) and the gate's lever arm
    /// (loop_gate_lever_arm).
    bool guessFreeSearch = false, contestedLoops = false, leverArmGate = false;
    /// Whether the scans between keyframes were placed by registration and odometry together
    /// (smooth_scans) or by registration alone.
    bool smoothedScans = false;
    /// Whether the odometry's distance scale was learnt and applied (odometry_calibration).
    bool odometryCalibration = false;
    std::optional<PoseGraph> graph;    ///< keyframe pose graph, optimised
    mrpt::maps::CSimpleMap keyframes;  ///< each keyframe's scan and features at its pose
};

/// Runs SLAM on `logPath` with the settings in `ini`: [Slam] engine (graph, the default, or
/// icp); the graph engine's sections (GraphSlamInput.h) or icp-slam's [MappingApplication]
/// and [ICP] (IcpEngine.h); and [OccupancyGrid] (OccupancyGridOptions, with the alignment of
/// the map to its dominant walls, ManhattanAlignment.h; a bad value there is a
/// config::ConfigError naming the file when `ini` is an mrpt::config::CConfigFile). Reports
/// progress through `progress` (fraction of the file read, scans). Throws io::InputError for
/// unreadable or malformed logs and for a log without scans, config::ConfigError for bad
/// settings and for a section no engine reads (the features' sections, CornerExtractor,
/// SegmentExtractor and SplitAndMergeExtractor, are known; so is MRPT's
/// [MappingApplication_*]).
MappingResult mapLog(const std::string& logPath, const mrpt::config::CConfigFileBase& ini,
                     const io::ProgressCallback& progress = {});

}  // namespace toposlam::mapping
