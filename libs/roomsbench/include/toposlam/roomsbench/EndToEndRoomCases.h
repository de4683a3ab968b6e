#pragma once
// Rooms on grids built by our own SLAM, end to end, as a user gets them: a simulated robot
// tours a floor plan with exact ground truth (simulation: tour planner, laser and odometry
// simulator), toposlam's SLAM maps the log (mapping::mapLog), and the SLAM grid and trajectory
// are segmented like any map. The SLAM map's frame is tied to the plan's by the rigid transform
// that best lays the SLAM trajectory on the simulator's ground-truth trajectory (poses matched
// by time stamp); labels are carried into the plan's image through it (nearest cell) and
// scored against the plan's rooms and doors (rooms::RoomBenchmark).
#include <toposlam/io/Trajectory.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace toposlam::roomsbench {

/// A floor plan to tour: a furnished map and its ground truth in one image frame.
struct PlanToTour {
    std::string name;
    double resolution = 0.05;  ///< m per pixel
    cv::Mat map;               ///< CV_8U: 255 free, 0 occupied, other values unknown
    cv::Mat unfurnishedFree;   ///< CV_8U, 255 = free in the unfurnished plan (true doors)
    cv::Mat roomLabels;        ///< CV_32S ground-truth rooms, 0 = none
};

/// The plans of the end-to-end set: generated office plans (seeds), Bormann maps (names, from
/// `bormannDir`; their furnished map is toured) and generated ring plans (ringSeeds). Throws
/// io::InputError for a missing map.
std::vector<PlanToTour> plansToTour(const std::vector<unsigned>& seeds,
                                    const std::vector<std::string>& bormannMaps,
                                    const std::string& bormannDir,
                                    const std::vector<unsigned>& ringSeeds = {});

/// toposlam-sim's defaults (config_ini/sim-office.ini), except that the tour also looks into
/// every area the room-sized tour leaves unseen ([Tour] look_into_unseen): as a person driving
/// the robot would, and a room no laser saw cannot be segmented by any method.
simulation::SimulatorConfig endToEndSimulatorDefaults();

struct EndToEndOptions {
    /// Tour, laser, odometry.
    simulation::SimulatorConfig simulator = endToEndSimulatorDefaults();
    /// toposlam-slam's settings (config_ini/toposlam-slam.ini).
    const mrpt::config::CConfigFileBase* slamConfig = nullptr;
    std::string workDir;  ///< where the simulated logs are written (created; files are kept)
    /// Drive these poses (the plan's frame, m and rad; stamps in s) instead of planning a tour:
    /// a recorded tour replayed, e.g. one that showed a failure. Empty: plan the tour.
    io::Trajectory2D poses;
};

/// What the run produced besides the case: for tables and pictures.
struct EndToEndRun {
    std::size_t scans = 0;
    double tourLength = 0;           ///< m
    double slamSeconds = 0;          ///< wall time of mapLog
    mrpt::math::TPose2D slamToPlan;  ///< SLAM map frame -> plan frame
    double alignmentRmse = 0;        ///< m, SLAM positions vs ground truth after the transform
    /// Ground-truth rooms (labels of the case's truth) of which less than a tenth is in line of
    /// sight of the tour (within [Tour] view_range): no SLAM of this log can map them (in
    /// Bormann's scanned maps, e.g., laser wedges drawn outside the building's walls).
    std::vector<int> roomsOutOfView;
};

/// Tours `plan`, maps the log, and returns the SLAM grid as a case of dataset "slam" (with the
/// SLAM trajectory), scored in the plan's image. Throws std::invalid_argument when the plan
/// has no room the robot fits in, io::InputError when SLAM cannot read its log.
rooms::RoomBenchmarkCase endToEndCase(const PlanToTour& plan, const EndToEndOptions& options,
                                      EndToEndRun& run);

/// The plan as drawn (dataset "drawn", no trajectory): the figures the SLAM ones compare to.
rooms::RoomBenchmarkCase drawnPlanCase(const PlanToTour& plan);

}  // namespace toposlam::roomsbench
