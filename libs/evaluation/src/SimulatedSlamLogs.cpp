#include <toposlam/evaluation/ChildProcess.h>
#include <toposlam/evaluation/SimulatedSlamLogs.h>
#include <toposlam/io/InputError.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace toposlam::evaluation {

namespace fs = std::filesystem;

const std::vector<SimulatedRobot>& simulatedRobots() {
    // Lasers as their data sheets give them; every odometry but poor-odometry's is the
    // simulator configuration's.
    static const std::vector<SimulatedRobot> robots = {
        {"lms1xx",
         "361 beams over 270 deg, 20 m, range noise 1 cm (toposlam-sim's configuration)",
         {},
         {}},
        {"lms200",
         "181 beams over 180 deg, 8 m (a SICK LMS200 in its 8 m mode, as on many CARMEN logs)",
         {"--beams", "181", "--fov-deg", "180", "--max-range", "8"},
         {}},
        {"urg-04lx",
         "682 beams over 240 deg, 5.6 m, range noise 2 cm (a Hokuyo URG-04LX)",
         {"--beams", "682", "--fov-deg", "240", "--max-range", "5.6", "--range-noise", "0.02"},
         {}},
        {"lds-01",
         "360 beams all round, 3.5 m, range noise 3 cm (a TurtleBot3's LDS-01: short range, "
         "much noise)",
         {"--beams", "360", "--fov-deg", "359", "--max-range", "3.5", "--range-noise", "0.03"},
         {{"Laser", "min_range", "0.12"}}},
        {"poor-odometry",
         "lms1xx laser; odometry 5 % long, turning 6 % too far, curving 1 deg per m, three "
         "times the random error",
         {},
         {{"Odometry", "distance_scale", "1.05"},
          {"Odometry", "rotation_scale", "1.06"},
          {"Odometry", "curvature_deg_per_m", "1.0"},
          {"Odometry", "rot_std_deg_per_sqrt_rad", "4.5"},
          {"Odometry", "rot_std_deg_per_sqrt_m", "1.5"},
          {"Odometry", "trans_std_m_per_sqrt_m", "0.045"},
          {"Odometry", "trans_std_m_per_sqrt_rad", "0.015"}}},
        {"people", "lms1xx laser; 15 people walking about at 0.8-1.3 m/s", {"--people", "15"}, {}},
        {"stalling-odometry",
         "lms1xx laser; odometry that stalls at 5 % of the scans for 1-3 scans, then catches up "
         "in one reading",
         {},
         {{"Odometry", "stall_probability", "0.05"}, {"Odometry", "stall_max_scans", "3"}}},
    };
    return robots;
}

const SimulatedRobot* findSimulatedRobot(const std::string& name) {
    const auto& robots = simulatedRobots();
    const auto it = std::find_if(robots.begin(), robots.end(),
                                 [&](const SimulatedRobot& r) { return r.name == name; });
    return it == robots.end() ? nullptr : &*it;
}

std::string simulatedLogName(const std::string& plan, const std::string& robot,
                             std::optional<unsigned> seed) {
    std::string stem = fs::path(plan).stem().string();
    const std::string furnished = "_furnitures";
    if (stem.size() > furnished.size() &&
        stem.compare(stem.size() - furnished.size(), furnished.size(), furnished) == 0)
        stem.resize(stem.size() - furnished.size());
    return stem + "." + robot + (seed ? ".seed" + std::to_string(*seed) : "");
}

std::vector<SlamBenchmarkLog> simulateSlamLogs(const SimulatedLogsRequest& request,
                                               const SimulationProgress& progress) {
    std::vector<const SimulatedRobot*> robots;
    for (const std::string& name : request.robots) {
        const SimulatedRobot* robot = findSimulatedRobot(name);
        if (!robot)
            throw std::invalid_argument("unknown robot '" + name + "'");
        robots.push_back(robot);
    }
    // Every tour and its log's name, plan by plan (the order they are simulated in).
    struct Tour {
        std::string plan;
        const SimulatedRobot* robot;
        std::optional<unsigned> seed;
        std::string name;
    };
    std::vector<std::optional<unsigned>> seeds(request.seeds.begin(), request.seeds.end());
    if (seeds.empty())
        seeds.push_back(std::nullopt);  // the configuration's seed
    std::vector<Tour> tours;
    for (const std::string& plan : request.plans) {
        if (!fs::is_regular_file(plan))
            throw io::InputError(plan, "floor plan not found");
        for (const SimulatedRobot* robot : robots) {
            for (const std::optional<unsigned>& seed : seeds) {
                const std::string name = simulatedLogName(plan, robot->name, seed);
                if (std::any_of(tours.begin(), tours.end(),
                                [&](const Tour& t) { return t.name == name; }))
                    throw std::invalid_argument("two logs would be named " + name +
                                                " (a plan, robot or seed given twice?)");
                tours.push_back({plan, robot, seed, name});
            }
        }
    }
    fs::create_directories(request.directory);
    const std::string directory = fs::absolute(request.directory).string();
    std::vector<SlamBenchmarkLog> logs;
    for (const Tour& tour : tours) {
        if (progress)
            progress(logs.size(), tours.size(), tour.name);
        const std::string base = directory + "/" + tour.name;
        std::string config = request.simulatorConfig;
        if (!tour.robot->settings.empty()) {
            config = base + ".sim.ini";
            writeIniWithSettings(request.simulatorConfig, config, tour.robot->settings);
        }
        // A drawn plan (grey furniture stops the laser), toured through every room.
        std::vector<std::string> argv = {request.simulator,
                                         fs::absolute(tour.plan).string(),
                                         "--drawn",
                                         "--tour",
                                         "-q",
                                         "-c",
                                         config,
                                         "-o",
                                         base + ".rawlog",
                                         "--gt",
                                         base + "_gt.txt"};
        argv.insert(argv.end(), tour.robot->simulatorArguments.begin(),
                    tour.robot->simulatorArguments.end());
        if (tour.seed)
            argv.insert(argv.end(), {"--seed", std::to_string(*tour.seed)});
        const ChildProcessResult sim =
            runChildProcessLogged(argv, directory, tour.name + ".sim-", request.timeoutSeconds);
        if (!sim.succeeded()) {
            const std::string detail = lastLineOf(base + ".sim-stderr.txt");
            throw std::runtime_error(
                "toposlam-sim on " + tour.plan + " with robot " + tour.robot->name +
                (tour.seed ? " (seed " + std::to_string(*tour.seed) + ")" : std::string()) + ": " +
                sim.describeFailure() + (detail.empty() ? "" : ": " + detail));
        }
        logs.push_back({tour.name, base + ".rawlog", "", base + "_gt.txt", tour.robot->name});
    }
    return logs;
}

}  // namespace toposlam::evaluation
