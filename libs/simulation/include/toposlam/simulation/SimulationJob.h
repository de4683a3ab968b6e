#pragma once
// What toposlam-sim does with a map, as a library: load the map, get the robot's poses (a
// pose file, or an automatic tour through every room-sized area), simulate the log and write
// it with its ground truth (and, if asked, a picture). Two steps, so that a caller can report
// the plan (tour length, poses not in free space) before the long simulation starts.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/SimulatorConfig.h>
#include <toposlam/simulation/TourPlanner.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::simulation {

struct SimulationJob {
    std::string mapPath;  ///< .gridmap[.gz], ROS .yaml, or an image (io::loadGridMap)
    /// Geometry of an image map without metadata (io::loadGridMap); none: its own / defaults.
    std::optional<io::GridMapGeometry> imageGeometry;
    /// Poses to follow ("timestamp x y yaw" lines, io::loadTrajectory); "" = plan a tour.
    std::string posesPath;
    std::string rawlogPath;       ///< output rawlog (.rawlog or .rawlog.gz)
    std::string groundTruthPath;  ///< output ground truth; "" = groundTruthPathFor(rawlogPath)
    std::string plotPath;         ///< PNG of the map with the trajectory; "" = none
};

struct SimulationPlan {
    mrpt::maps::COccupancyGridMap2D map;
    io::Trajectory2D poses;                   ///< ground truth, one scan each (map frame)
    std::optional<Tour> tour;                 ///< the planned tour, when no pose file was given
    std::vector<mrpt::math::TPoint2D> marks;  ///< tour: area centres in visiting order
    std::size_t posesNotFree = 0;             ///< pose file: poses outside free cells
};

/// "out.rawlog[.gz]" -> "out_gt.txt".
std::string groundTruthPathFor(const std::string& rawlogPath);

/// Loads the map and gets the poses. Throws io::InputError naming the map or pose file when
/// it cannot be read, has no free cell, admits no tour, or a pose lies outside the map.
SimulationPlan planSimulation(const SimulatorConfig& config, const SimulationJob& job);

/// Simulates the plan and writes the rawlog and ground truth (both or neither) and the plot.
/// Returns the number of scans written. Bad pose sequences (stamps) are io::InputError.
std::size_t runSimulation(const SimulationPlan& plan, const SimulatorConfig& config,
                          const SimulationJob& job, const io::ProgressCallback& progress = {});

}  // namespace toposlam::simulation
