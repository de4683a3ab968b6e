// toposlam-bench-slam: benchmark B3 in one command. TopoSLAM's graph SLAM, its icp engine and
// MRPT's stock icp-slam on every public log with relations and on the simulated office, one
// run after the other, scored with the relation metric of Kümmerle et al. 2009; optionally
// also on simulated tours of floor plans with several robots (--sim-plans). The work is done
// by libs/evaluation (SlamBenchmark, SimulatedSlamLogs); this app reads the options and prints.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/LogAlterationArgs.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/cli/UsageError.h>
#include <toposlam/evaluation/ChildProcess.h>
#include <toposlam/evaluation/SimulatedSlamLogs.h>
#include <toposlam/evaluation/SlamBenchmark.h>
#include <toposlam/evaluation/SlamBenchmarkReport.h>
#include <toposlam/io/InputError.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace toposlam;

const char* const kDescription =
    "Benchmark B3 in one run: SLAM accuracy and cost of TopoSLAM's graph SLAM (toposlam-slam, "
    "engine = graph), of its icp engine (the same configuration with [Slam] engine = icp: "
    "MRPT's CMetricMapBuilderICP) and of MRPT's stock icp-slam (when installed, Debian package "
    "mrpt-apps; its configuration is the peer one of the benchmarks, on the log converted to a "
    "rawlog by toposlam-convert), on every log of --data that has a .relations file (Kuemmerle "
    "et al. 2009: intel, fr079, mit-csail), on the simulated office (share/office) and on "
    "MRPT's simulated sample log (mrpt-simul: ../shared/data/rawlog/simul.rawlog, when there), "
    "the last two scored against their ground truth (derived relations and ATE). Runs are "
    "sequential child processes, "
    "so each one's wall time, CPU time (user + system) and peak RSS are its own. Prints a "
    "Markdown table (relations matched, translational and rotational error mean +- std, "
    "squared errors, maxima, ATE, wall and CPU time, real-time factor = log duration / wall "
    "time and / CPU time, peak RSS, loop closures accepted / rejected / withdrawn) and numbered "
    "notes on failed or skipped runs; progress goes to stderr.\n"
    "With --sim-plans it first simulates a tour of each floor plan with each robot of "
    "--sim-robots (toposlam-sim, exact ground truth; logs <plan>.<robot> in --sim-dir), with "
    "--sim-seeds once per seed, and runs the engines on those logs too: SLAM on data it was not "
    "tuned on, with lasers and odometry harder than the public logs'; a table by robot sums "
    "them up (ATE mean, spread, median, worst log). With --keep-every N every log runs with one "
    "scan in N: more motion between two scans, as a slower laser or a faster robot gives; with "
    "--keep-beam-every N one beam in N: a coarser laser; with --clip-range R no reading beyond R "
    "m: a laser that sees less far.\n"
    "Examples:\n"
    "  toposlam-bench-slam --json b3.json --images b3-img\n"
    "  toposlam-bench-slam --logs intel,office --engines graph,icp-slam --keep b3-runs\n"
    "  toposlam-bench-slam --sim-plans office_d,NLB --sim-robots lms200,urg-04lx\n"
    "  toposlam-bench-slam --sim-plans office_d,NLB --sim-seeds 1-3 --engines graph\n"
    "  toposlam-bench-slam --logs fr079,intel --keep-every 3\n"
    "  toposlam-bench-slam --logs mit-csail,fr079 --engines graph --keep-beam-every 2\n"
    "  toposlam-bench-slam --logs intel,fr079,mit-csail --clip-range 5.6\n"
    "Exit status: 0 when every run succeeded (or, with 'B3 skipped: ...' on stderr, when the "
    "benchmark logs are not there); 1 when a run failed (the table says which and why) or on "
    "bad input (missing configuration, plan or a failing simulation); 2 for bad usage (unknown "
    "option, log, engine, robot or seed).";

std::vector<evaluation::SlamEngine> parseEngines(const std::string& text) {
    std::vector<evaluation::SlamEngine> engines;
    for (const std::string& name : cli::splitList(text)) {
        const auto engine = evaluation::engineFromName(name);
        if (!engine)
            throw cli::UsageError("--engines: unknown engine '" + name +
                                  "' (graph, icp, icp-slam)");
        if (std::find(engines.begin(), engines.end(), *engine) != engines.end())
            throw cli::UsageError("--engines: '" + name + "' given twice");
        engines.push_back(*engine);
    }
    if (engines.empty())
        throw cli::UsageError("--engines: no engine given");
    return engines;
}

// The programs this one runs live beside it in bin/.
std::string besideMe(const std::string& program) {
    const fs::path path = fs::read_symlink("/proc/self/exe").parent_path() / program;
    if (evaluation::findExecutable(path.string()).empty())
        throw std::runtime_error(path.string() + ": not found (build it: it runs the benchmark)");
    return path.string();
}

// "lms1xx,lms200,...": every simulated robot.
std::string robotNames() {
    std::string names;
    for (const auto& robot : evaluation::simulatedRobots())
        names += (names.empty() ? "" : ",") + robot.name;
    return names;
}

std::string robotsHelp() {
    std::string help = "Comma-separated robots that tour every --sim-plans plan:";
    for (const auto& robot : evaluation::simulatedRobots())
        help += " " + robot.name + " (" + robot.description + ");";
    return help + " Default: all";
}

// The command line; TCLAP's arguments register with `cmd`, declared first.
struct Arguments {
    Arguments();
    TCLAP::CmdLine cmd;
    TCLAP::ValueArg<std::string> data, logs, engines, config, icpSlam, icpSlamConfig, keep, images,
        json, simPlans, simRobots, simSeeds, simDir, simConfig;
    cli::NumberArg<double> timeout;
    TCLAP::SwitchArg robotFrame;
    cli::LogAlterationArgs alteration;
};

Arguments::Arguments()
    : cmd(kDescription, ' ', "0.1"),
      data("d", "data",
           "Folder of the public logs: every <name>.relations with its "
           "<name>.clf/.log/.rawlog[.gz]; absent: prints 'B3 skipped' and exits 0. "
           "Default: " TOPOSLAM_SHARED_DATA_DIR "/slam",
           false, TOPOSLAM_SHARED_DATA_DIR "/slam", "dir", cmd),
      logs("", "logs",
           "Comma-separated logs to run, in this order: names of --data's logs (intel, fr079, "
           "mit-csail), 'office' (the simulated office) and 'mrpt-simul' (MRPT's simulated "
           "sample log, " TOPOSLAM_SHARED_DATA_DIR
           "/rawlog/simul.rawlog, with its ground truth "
           "simul.rawlog.GT.txt). Default: all; 'office' alone needs no --data",
           false, "", "list", cmd),
      engines("", "engines",
              "Comma-separated engines (table rows per log): graph, icp, icp-slam. Default: all "
              "three",
              false, "graph,icp,icp-slam", "list", cmd),
      config("c", "config",
             "toposlam-slam configuration of the graph and icp rows ([Slam] engine is set per "
             "row in a copy). Default: " TOPOSLAM_SOURCE_DIR "/config_ini/toposlam-slam.ini",
             false, TOPOSLAM_SOURCE_DIR "/config_ini/toposlam-slam.ini", "file.ini", cmd),
      icpSlam("", "icp-slam",
              "MRPT's icp-slam executable (a name is looked up in PATH); when not found, its "
              "rows are reported as not run. Default: icp-slam",
              false, "icp-slam", "program", cmd),
      icpSlamConfig("", "icp-slam-config",
                    "icp-slam configuration (logOutput_dir is replaced in a copy). "
                    "Default: " TOPOSLAM_SHARED_DATA_DIR "/../peers/icp-slam-benchmark.ini",
                    false, TOPOSLAM_SHARED_DATA_DIR "/../peers/icp-slam-benchmark.ini", "file.ini",
                    cmd),
      keep("", "keep",
           "Keep every run's folder under this one (<log>/<engine>/: the configuration written "
           "for it, the engine's outputs in out/, stdout.txt, stderr.txt). Default: a temporary "
           "folder, removed at the end",
           false, "", "dir", cmd),
      images("", "images",
             "Write <log>-maps.png (each engine's occupancy grid side by side, same scale) and "
             "<log>-trajectories.png (the trajectories, aligned) into this folder",
             false, "", "dir", cmd),
      json("", "json", "Write the results as JSON to this file (keys: share/doc/apps.md)", false,
           "", "out.json", cmd),
      simPlans("", "sim-plans",
               "Comma-separated drawn floor plans to tour with every --sim-robots robot: names of "
               "Bormann's maps (" TOPOSLAM_SHARED_DATA_DIR
               "/rooms/<name>_furnitures.png, e.g. office_d, NLB, lab_intel, Freiburg79_scan) "
               "or plan images (white free, darker obstacles; a name with '/' or '.png'). Their "
               "logs are named <plan>.<robot> and run after those of --logs (without --logs, "
               "only they run). Default: none",
               false, "", "list", cmd),
      simRobots("", "sim-robots", robotsHelp(), false, robotNames(), "list", cmd),
      simSeeds("", "sim-seeds",
               "Tour every plan with every robot once per seed (toposlam-sim --seed: the same "
               "tour, other laser noise, odometry errors and people), e.g. 1-5 or 2,7; logs "
               "<plan>.<robot>.seed<N>. One tour's outcome is partly chance: with several "
               "seeds the table by robot (ATE mean, spread, median, worst) says what is. "
               "Default: one tour with the configuration's seed, logs <plan>.<robot>",
               false, "", "list", cmd),
      simDir("", "sim-dir",
             "Where the simulated logs go (<plan>.<robot>.rawlog, its _gt.txt, toposlam-sim's "
             "output). Default: b3-sim-logs",
             false, "b3-sim-logs", "dir", cmd),
      simConfig("", "sim-config",
                "toposlam-sim configuration the robots start from (its tour and the lms1xx "
                "laser). Default: " TOPOSLAM_SOURCE_DIR "/config_ini/sim-office.ini",
                false, TOPOSLAM_SOURCE_DIR "/config_ini/sim-office.ini", "file.ini", cmd),
      timeout("", "timeout",
              "Kill a run after this many seconds of wall time (0: no limit, the default).", 0.0,
              cli::NumberRange<double>::nonNegative(1e6), "seconds", cmd),
      robotFrame("", "robot-frame",
                 "Score relation logs as the robot's poses the engines give, also where a log "
                 "puts its laser off the robot's centre (ROBOTLASER lines): for relations made "
                 "in the robot's frame. Default: at the laser each scan states, the frame of "
                 "Kuemmerle et al.'s relations (the same where the laser is at the centre)",
                 cmd),
      alteration(
          cmd, {"Every log runs so, named <log>-1inN and scored on the relations "
                "between kept scans.",
                "Every log runs so, named <log>-beams1inN.", "Every log runs so, named <log>-toRm.",
                "Every log runs so, named <log>-laseronly.",
                "Every log runs so, named <log>-mirrored and scored on the mirror image of its "
                "relations or ground truth."}) {}

// "/work/wt/../shared/data" -> "/work/shared/data": shorter names in the table. Absolute, since
// the runs' child processes work in folders of their own ("" stays "": not given).
std::string tidy(const std::string& path) {
    return path.empty() ? path : fs::absolute(path).lexically_normal().string();
}

// A --sim-plans item: a plan image, or the furnished plan of a Bormann map of that name.
std::string planImage(const std::string& item) {
    if (item.find('/') != std::string::npos || fs::path(item).extension() == ".png")
        return tidy(item);
    return tidy(TOPOSLAM_SHARED_DATA_DIR "/rooms/" + item + "_furnitures.png");
}

// Simulates the --sim-plans logs (progress on stderr) and adds them to the run.
void addSimulatedLogs(Arguments& a, evaluation::SlamBenchmarkOptions& options) {
    evaluation::SimulatedLogsRequest request;
    request.seeds = cli::parseSeedList(a.simSeeds.getValue(), "--sim-seeds");
    for (const std::string& item : cli::splitList(a.simPlans.getValue()))
        request.plans.push_back(planImage(item));
    if (request.plans.empty())
        return;
    request.robots = cli::splitList(a.simRobots.getValue());
    if (request.robots.empty())
        throw cli::UsageError("--sim-robots: no robot given");
    request.simulator = besideMe("toposlam-sim");
    request.simulatorConfig = tidy(a.simConfig.getValue());
    request.directory = tidy(a.simDir.getValue());
    request.timeoutSeconds = a.timeout.getValue();
    const auto progress = [](std::size_t done, std::size_t total, const std::string& next) {
        std::cerr << "simulating " << done + 1 << "/" << total << ": " << next << " ..."
                  << std::endl;
    };
    std::vector<evaluation::SlamBenchmarkLog> logs;
    try {
        logs = evaluation::simulateSlamLogs(request, progress);
    } catch (const std::invalid_argument& e) {  // an unknown robot, two logs of one name
        throw cli::UsageError(std::string("--sim-plans, --sim-robots: ") + e.what() +
                              " (robots: " + robotNames() + ")");
    }
    // After the logs of --logs (with none, the simulated ones alone).
    for (const auto& log : logs) {
        options.simulatedLogs.push_back(log);
        options.logs.push_back(log.name);
    }
}

// The benchmark options from the command line. Throws cli::UsageError for bad usage.
evaluation::SlamBenchmarkOptions benchmarkOptions(Arguments& a) {
    evaluation::SlamBenchmarkOptions options;
    options.dataDir = tidy(a.data.getValue());
    options.simulatedLogs.push_back({"office",
                                     tidy(TOPOSLAM_SOURCE_DIR "/share/office/office.rawlog"), "",
                                     tidy(TOPOSLAM_SOURCE_DIR "/share/office/office_gt.txt"), ""});
    // MRPT's own simulated sample log, with the ground truth its simulator wrote: a noisier
    // laser than the public logs' (2-5 cm), 80 m range in a 90 x 60 m hall, and frames dropped
    // for up to 2 s. Present only with the shared data.
    const std::string mrptSimul = TOPOSLAM_SHARED_DATA_DIR "/rawlog/simul.rawlog";
    if (fs::exists(mrptSimul) && fs::exists(mrptSimul + ".GT.txt"))
        options.simulatedLogs.push_back(
            {"mrpt-simul", tidy(mrptSimul), "", tidy(mrptSimul + ".GT.txt"), ""});
    options.logs = cli::splitList(a.logs.getValue());
    options.engines = parseEngines(a.engines.getValue());
    options.keepDir = a.keep.getValue();
    options.imageDir = a.images.getValue();
    options.alteration = a.alteration.alteration();
    options.robotFrame = a.robotFrame.getValue();
    evaluation::SlamEngineSetup& setup = options.setup;
    setup.timeoutSeconds = a.timeout.getValue();
    setup.slamConfig = tidy(a.config.getValue());
    setup.icpSlamConfig = tidy(a.icpSlamConfig.getValue());
    setup.icpSlam = evaluation::findExecutable(a.icpSlam.getValue());
    if (setup.icpSlam.empty())
        std::cerr << "note: " << a.icpSlam.getValue() << " not found: its rows are not run\n";
    setup.toposlamSlam = besideMe("toposlam-slam");
    setup.toposlamConvert = besideMe("toposlam-convert");
    addSimulatedLogs(a, options);
    return options;
}

int run(int argc, char** argv) {
    Arguments a;
    if (const auto exitCode = cli::parseCommandLine(a.cmd, argc, argv))
        return *exitCode;
    std::optional<evaluation::SlamBenchmark> bench;
    try {
        bench.emplace(benchmarkOptions(a));
    } catch (const cli::UsageError&) {
        throw;
    } catch (const std::invalid_argument& e) {  // the log selection (engines are checked here)
        throw cli::UsageError(std::string("--logs: ") + e.what());
    }
    if (!bench->skipReason().empty()) {
        std::cerr << "B3 skipped: " << bench->skipReason()
                  << "; get shared/data/slam or pass --data\n";
        return EXIT_SUCCESS;
    }
    if (!fs::is_regular_file(a.config.getValue()))
        throw io::InputError(a.config.getValue(), "configuration file not found");

    const auto runs = bench->runs();
    const auto result = bench->run([&](double, std::size_t done) {
        if (done < runs.size()) {
            std::cerr << "[" << done + 1 << "/" << runs.size() << "] " << runs[done].first << " "
                      << evaluation::engineName(runs[done].second) << " ..." << std::endl;
        }
    });
    std::cout << evaluation::formatSlamBenchmarkTable(result);
    if (a.json.isSet()) {
        evaluation::saveSlamBenchmarkJson(result, a.json.getValue());
        std::cerr << "wrote " << a.json.getValue() << "\n";
    }
    for (const auto& log : result.logs) {
        for (const std::string& image : log.images)
            std::cerr << "wrote " << image << "\n";
    }
    if (!result.workDirectory.empty())
        std::cerr << "runs kept in " << result.workDirectory << "\n";
    return result.anyFailed() ? EXIT_FAILURE : EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return cli::runReportingErrors(run, argc, argv);
}
