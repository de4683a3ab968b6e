#pragma once
// Simulated logs for benchmark B3 beyond the three public logs: a robot touring drawn floor
// plans (Bormann's, or any plan image) with one of a few typical lasers and odometries, each
// log written by toposlam-sim with its exact ground truth. The SLAM was tuned on none of these
// tours; the robots differ in what makes SLAM hard on real logs: short range and a narrow
// field of view (corridors the laser cannot see the end of), odometry that reads long and
// curves, people walking through the scans.
#include <toposlam/evaluation/IniWithSettings.h>
#include <toposlam/evaluation/SlamBenchmarkLog.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::evaluation {

/// A robot for simulated logs: how it differs from toposlam-sim's configuration
/// (config_ini/sim-office.ini: 361 beams over 270 deg, 20 m, range noise 1 cm; odometry 1 %
/// long, 1.5 % over-turning).
struct SimulatedRobot {
    std::string name;         ///< e.g. "urg-04lx"
    std::string description;  ///< one line, for --help and the report
    /// toposlam-sim options (--beams, --fov-deg, --max-range, --range-noise, --people).
    std::vector<std::string> simulatorArguments;
    /// Keys replaced in a copy of the simulator configuration (the [Odometry] error model).
    std::vector<IniSetting> settings;
};

/// Every robot, in report order: lms1xx, lms200, urg-04lx, lds-01, poor-odometry, people,
/// stalling-odometry.
const std::vector<SimulatedRobot>& simulatedRobots();

/// The robot of that name, or nullptr.
const SimulatedRobot* findSimulatedRobot(const std::string& name);

struct SimulatedLogsRequest {
    /// Drawn floor plans (images: white free, anything darker an obstacle, toposlam-sim
    /// --drawn), e.g. Bormann's `<map>_furnitures.png`.
    std::vector<std::string> plans;
    std::vector<std::string> robots;  ///< names (simulatedRobots())
    std::string simulator;            ///< toposlam-sim executable
    std::string simulatorConfig;      ///< its .ini (config_ini/sim-office.ini)
    std::string directory;            ///< where the logs go (created)
    double timeoutSeconds = 0;        ///< per simulation; <= 0: none
    /// toposlam-sim --seed of each tour: every plan and robot toured once per seed (the same
    /// tour; the laser noise, odometry errors and people differ). Empty = once, with the
    /// configuration's seed.
    std::vector<unsigned> seeds;
};

/// The log name of a plan and robot: "<plan file stem without _furnitures>.<robot>", e.g.
/// "office_d.urg-04lx", and with a seed "office_d.urg-04lx.seed3".
std::string simulatedLogName(const std::string& plan, const std::string& robot,
                             std::optional<unsigned> seed = std::nullopt);

/// Called before each simulation with the logs simulated so far, the number of logs and the
/// name of the one about to be simulated.
using SimulationProgress =
    std::function<void(std::size_t done, std::size_t total, const std::string& next)>;

/// Simulates a tour of every plan with every robot (plan by plan; per robot, seed by seed),
/// each into `<directory>/<name>.rawlog` with its ground truth `<name>_gt.txt` and toposlam-sim's
/// output `<name>.sim-stdout.txt`, `<name>.sim-stderr.txt` (always simulated anew: the same
/// plan, robot, seed and configuration give the same log); each log's group is its robot.
/// Throws std::invalid_argument for an unknown robot or two logs of one name (plans of one
/// file name, a robot or seed given twice), io::InputError for a plan that is not there,
/// std::runtime_error naming the plan, the robot (and seed) and toposlam-sim's last message
/// when a simulation fails.
std::vector<SlamBenchmarkLog> simulateSlamLogs(const SimulatedLogsRequest& request,
                                               const SimulationProgress& progress = {});

}  // namespace toposlam::evaluation
