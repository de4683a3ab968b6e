#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/evaluation/IniWithSettings.h>
#include <toposlam/evaluation/SlamEngineRun.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

namespace fs = std::filesystem;

constexpr double kDefaultResolution = 0.05;  // m, MRPT's and toposlam-slam's grid default

// "<what>: exit status 1: error: intel.clf: line 3: ..." from the process and its output.
std::string failureNote(const std::string& what, const ChildProcessResult& process,
                        const fs::path& dir, const std::string& prefix) {
    std::string note = what + ": " + process.describeFailure();
    std::string detail = lastLineOf((dir / (prefix + "stderr.txt")).string());
    if (detail.empty())
        detail = lastLineOf((dir / (prefix + "stdout.txt")).string());
    return detail.empty() ? note : note + ": " + detail;
}

void runToposlamSlam(SlamEngineRun& run, const SlamBenchmarkLog& log, const SlamEngineSetup& setup,
                     const fs::path& dir) {
    const fs::path ini = dir / "toposlam-slam.ini";
    writeIniWithSettings(setup.slamConfig, ini.string(),
                         {{"Slam", "engine", run.engine == SlamEngine::Icp ? "icp" : "graph"}});
    const fs::path out = dir / "out";
    run.process =
        runChildProcessLogged({setup.toposlamSlam, ini.string(), log.logFile, "-o", out.string()},
                              dir.string(), "", setup.timeoutSeconds);
    if (!run.process.succeeded()) {
        run.note = failureNote("toposlam-slam", run.process, dir, "");
        return;
    }
    run.trajectory = io::loadTrajectory((out / "trajectory.txt").string());
    std::ifstream summary(out / "summary.json");
    run.summary = nlohmann::json::parse(summary, nullptr, false);
    if (run.summary.is_discarded()) {
        run.summary = nullptr;
        run.note = "no readable summary.json";
    } else if (run.summary.value("mostly_unregistered", false)) {
        run.note = "WARNING: most scans could not be registered (mostly raw odometry)";
    } else if (run.summary.value("weak_front_end", false)) {
        run.note = "WARNING: ICP registered less than 90 % of the scans (the map may be distorted)";
    }
    if (fs::is_regular_file(out / "map.png"))
        run.mapImage = (out / "map.png").string();
    run.mapResolution =
        readIniNumber(setup.slamConfig, "OccupancyGrid", "resolution", kDefaultResolution);
    run.status = SlamEngineRun::Status::Ok;
}

// icp-slam's grid picture: _finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00.png.
std::string icpSlamGridImage(const fs::path& out) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(out, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.find("COccupancyGridMap2D") != std::string::npos &&
            entry.path().extension() == ".png") {
            return entry.path().string();
        }
    }
    return "";
}

void runIcpSlam(SlamEngineRun& run, const SlamBenchmarkLog& log,
                const std::vector<double>& scanStamps, const SlamEngineSetup& setup,
                const fs::path& dir) {
    if (setup.icpSlam.empty()) {
        run.status = SlamEngineRun::Status::Skipped;
        run.note = "icp-slam is not installed (Debian package mrpt-apps)";
        return;
    }
    if (!fs::is_regular_file(setup.icpSlamConfig)) {
        run.status = SlamEngineRun::Status::Skipped;
        run.note = "icp-slam configuration not found: " + setup.icpSlamConfig;
        return;
    }
    const fs::path rawlog = dir / (log.name + ".rawlog");
    run.conversion =
        runChildProcessLogged({setup.toposlamConvert, log.logFile, "-o", rawlog.string()},
                              dir.string(), "convert-", setup.timeoutSeconds);
    if (!run.conversion->succeeded()) {
        run.note = failureNote("toposlam-convert", *run.conversion, dir, "convert-");
        return;
    }
    // icp-slam wipes its output folder at start: a folder of its own, inside the run's.
    const fs::path out = dir / "out";
    const fs::path ini = dir / "icp-slam.ini";
    writeIniWithSettings(setup.icpSlamConfig, ini.string(),
                         {{"MappingApplication", "logOutput_dir", out.string()}});
    run.process = runChildProcessLogged({setup.icpSlam, ini.string(), rawlog.string()},
                                        dir.string(), "", setup.timeoutSeconds);
    if (!run.process.succeeded()) {
        run.note = failureNote("icp-slam", run.process, dir, "");
        return;
    }
    run.trajectory =
        loadIcpSlamPath((out / "log_estimated_path.txt").string(), rawlog.string(), &scanStamps);
    run.mapImage = icpSlamGridImage(out);
    run.mapResolution =
        readIniNumber(setup.icpSlamConfig, "MappingApplication_occupancyGrid_00_creationOpts",
                      "resolution", kDefaultResolution);
    run.status = SlamEngineRun::Status::Ok;
}

}  // namespace

const char* engineName(SlamEngine engine) {
    switch (engine) {
        case SlamEngine::Graph:
            return "graph";
        case SlamEngine::Icp:
            return "icp";
        case SlamEngine::IcpSlam:
            return "icp-slam";
    }
    return "?";
}

std::optional<SlamEngine> engineFromName(const std::string& name) {
    for (const SlamEngine e : {SlamEngine::Graph, SlamEngine::Icp, SlamEngine::IcpSlam}) {
        if (name == engineName(e))
            return e;
    }
    return std::nullopt;
}

SlamEngineRun runSlamEngine(SlamEngine engine, const SlamBenchmarkLog& log,
                            const std::vector<double>& scanStamps, const SlamEngineSetup& setup,
                            const std::string& runDirectory) {
    SlamEngineRun run;
    run.engine = engine;
    try {
        const fs::path dir = fs::absolute(runDirectory);
        fs::create_directories(dir);
        if (engine == SlamEngine::IcpSlam)
            runIcpSlam(run, log, scanStamps, setup, dir);
        else
            runToposlamSlam(run, log, setup, dir);
    } catch (const std::exception& e) {
        run.status = SlamEngineRun::Status::Failed;
        run.note = e.what();
    }
    if (run.status != SlamEngineRun::Status::Ok)
        run.trajectory.clear();
    return run;
}

}  // namespace toposlam::evaluation
