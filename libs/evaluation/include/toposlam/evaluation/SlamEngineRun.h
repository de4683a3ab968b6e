#pragma once
// One SLAM engine run on one log for benchmark B3, as a child process (ChildProcess.h), so
// that its time and memory are its own:
//   graph     toposlam-slam with the given config, [Slam] engine = graph
//   icp       the same config with [Slam] engine = icp (MRPT's CMetricMapBuilderICP)
//   icp-slam  MRPT's stock icp-slam with the peer config, on the log converted to an
//             observations rawlog by toposlam-convert; its per-entry log_estimated_path.txt is
//             turned into per-scan poses by IcpSlamPath.h
// Every run gets its own folder holding the configuration written for it, the engine's
// outputs (out/) and its stdout.txt / stderr.txt.
#include <toposlam/evaluation/ChildProcess.h>
#include <toposlam/evaluation/SlamBenchmarkLog.h>
#include <toposlam/io/Trajectory.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::evaluation {

enum class SlamEngine { Graph, Icp, IcpSlam };

/// "graph", "icp", "icp-slam".
const char* engineName(SlamEngine engine);
/// The engine of that name, or nullopt.
std::optional<SlamEngine> engineFromName(const std::string& name);

/// Where the programs and the configurations are.
struct SlamEngineSetup {
    std::string toposlamSlam;     ///< toposlam-slam executable
    std::string toposlamConvert;  ///< toposlam-convert executable (icp-slam's rawlog)
    std::string icpSlam;          ///< MRPT's icp-slam executable; "" = not installed
    std::string slamConfig;       ///< toposlam-slam .ini (graph and icp rows)
    std::string icpSlamConfig;    ///< icp-slam .ini (its logOutput_dir is replaced)
    double timeoutSeconds = 0;    ///< per child process; <= 0: none
};

struct SlamEngineRun {
    enum class Status { Ok, Failed, Skipped };
    SlamEngine engine = SlamEngine::Graph;
    Status status = Status::Failed;
    /// Why the run failed or was skipped, or a warning about a run that finished.
    std::string note;
    ChildProcessResult process;  ///< the engine's process (not the conversion)
    /// icp-slam: the CARMEN -> rawlog conversion that preceded it (not counted in `process`).
    std::optional<ChildProcessResult> conversion;
    /// Robot pose at every scan, stamps as the log prints them (Ok runs).
    io::Trajectory2D trajectory;
    /// The engine's occupancy grid as a PNG in the run folder ("" when it wrote none), and its
    /// cell size (m per pixel).
    std::string mapImage;
    double mapResolution = 0.05;
    /// toposlam-slam's summary.json (null for icp-slam or when unreadable).
    nlohmann::json summary;
};

/// Runs `engine` on `log` in `runDirectory` (created). `scanStamps`: the file stamps of the
/// log's scans in order (LogOdometry.h), which give icp-slam's lines their stamps. Does not
/// throw for a failing or missing engine: the result says what happened.
SlamEngineRun runSlamEngine(SlamEngine engine, const SlamBenchmarkLog& log,
                            const std::vector<double>& scanStamps, const SlamEngineSetup& setup,
                            const std::string& runDirectory);

}  // namespace toposlam::evaluation
