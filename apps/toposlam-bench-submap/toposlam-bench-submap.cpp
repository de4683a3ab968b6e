// toposlam-bench-submap: the graph SLAM front end's two hot loops as Google Benchmarks, on a
// log's scans at its odometry poses, with the [GraphSlam] settings of an .ini (default
// config_ini/toposlam-slam.ini):
//   insert/<log>  LineMap::insertSurface: every third scan, a keyframe, goes into the line map
//                 of its submap (20 keyframes each), as mapping::Submap::insert does: fusing
//                 into the map's points, then stamping the lookup grid around each new one.
//                 Counter keyframes/s.
//   icp/<log>     PointToLineIcp::refineOnMap: every scan registered on its submap's line map,
//                 from its odometry pose moved by (5 cm, -5 cm, 2 deg), as ScanRegistration
//                 does. Counters scans/s and iterations (per scan).
// Logs: share/office/office.rawlog (the demo's), and with --data <dir> (default ../shared/data)
// slam/intel.clf, slam/fr079.clf and rawlog/simul.rawlog, the first 3000 scans of each.
#include <benchmark/benchmark.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PointToLineIcp.h>
#include <toposlam/matching/PolarScan.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace toposlam;

const char* const kHelp =
    "toposlam-bench-submap: the graph SLAM front end's hot loops (Google Benchmark), on each "
    "log's scans at its odometry poses:\n"
    "  insert/<log>  LineMap::insertSurface: keyframes (every third scan) into their submap's "
    "line map (20 keyframes per submap); counter keyframes/s\n"
    "  icp/<log>     PointToLineIcp::refineOnMap: every scan on its submap's line map, from "
    "its odometry pose moved by (5 cm, -5 cm, 2 deg); counters scans/s, iterations per scan\n"
    "Logs: share/office/office.rawlog; with the data folder also slam/intel.clf, "
    "slam/fr079.clf, rawlog/simul.rawlog (the first 3000 scans of each)\n"
    "Options: --data <dir>  public data (default " TOPOSLAM_SHARED_DATA_DIR
    ")\n"
    "         -c <file.ini>  [GraphSlam] settings (default " TOPOSLAM_SOURCE_DIR
    "/config_ini/toposlam-slam.ini)\n"
    "Google Benchmark flags are passed on, e.g. --benchmark_filter=icp "
    "--benchmark_repetitions=5 --benchmark_out=submap.json\n";

constexpr std::size_t kMaxScans = 3000;
constexpr std::size_t kKeyframeEvery = 3;
constexpr std::size_t kSubmapKeyframes = 20;
constexpr std::size_t kSubmapScans = kKeyframeEvery * kSubmapKeyframes;

/// A log cut into submaps: its scans, their sensor poses (odometry frame, m, rad), each
/// keyframe's surface points (matching::surfacePoints, computed once as the SLAM does) and each
/// submap's line map, built once for the ICP benchmark.
struct SubmapLog {
    std::string name;
    std::vector<matching::PolarScan> scans;
    std::vector<mrpt::poses::CPose2D> sensorPoses;
    std::vector<std::vector<matching::SurfacePoint>> surfaces;  // per scan; keyframes only
    std::vector<matching::LineMap> submaps;                     // scan i: submaps[i / 60]
};

void insertKeyframes(const SubmapLog& log, std::size_t submap, matching::LineMap& map) {
    map.reset();
    const std::size_t end = std::min(log.scans.size(), (submap + 1) * kSubmapScans);
    for (std::size_t i = submap * kSubmapScans; i < end; i += kKeyframeEvery)
        map.insertSurface(log.surfaces[i], log.sensorPoses[i]);
}

SubmapLog readLog(const std::string& name, const std::string& path,
                  const mapping::GraphSlamOptions& options) {
    SubmapLog log;
    log.name = name;
    io::LaserLogReader reader(path);
    io::LaserLogRecord record;
    const matching::LineMapOptions mapOptions = options.lineMapOptions();
    while (log.scans.size() < kMaxScans && reader.next(record)) {
        log.scans.emplace_back().assign(*record.scan);
        log.sensorPoses.push_back(record.odometry + mrpt::poses::CPose2D(record.scan->sensorPose));
        auto& surface = log.surfaces.emplace_back();
        if ((log.scans.size() - 1) % kKeyframeEvery == 0)
            matching::surfacePoints(log.scans.back(), mapOptions, surface);
    }
    if (log.scans.empty())
        throw io::InputError(path, "no scans");
    const std::size_t submaps = (log.scans.size() + kSubmapScans - 1) / kSubmapScans;
    for (std::size_t s = 0; s < submaps; ++s)
        insertKeyframes(log, s, log.submaps.emplace_back(mapOptions));
    return log;
}

void insert(benchmark::State& state, const SubmapLog* log,
            const mapping::GraphSlamOptions* options) {
    matching::LineMap map(options->lineMapOptions());
    for (auto _ : state) {
        for (std::size_t s = 0; s < log->submaps.size(); ++s)
            insertKeyframes(*log, s, map);
        benchmark::DoNotOptimize(map.size());
    }
    const auto keyframes = (log->scans.size() + kKeyframeEvery - 1) / kKeyframeEvery;
    state.counters["keyframes/s"] = benchmark::Counter(
        static_cast<double>(keyframes), benchmark::Counter::kIsIterationInvariantRate);
}

void icp(benchmark::State& state, const SubmapLog* log, const mapping::GraphSlamOptions* options) {
    const matching::IcpOptions icpOptions = options->icpOptions();
    const mrpt::poses::CPose2D offset(0.05, -0.05, 2.0 * M_PI / 180.0);
    matching::PointToLineIcp matcher;
    double iterations = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < log->scans.size(); ++i) {
            const matching::IcpResult r =
                matcher.refineOnMap(log->submaps[i / kSubmapScans], log->scans[i],
                                    log->sensorPoses[i] + offset, icpOptions);
            iterations += r.iterations;
        }
    }
    const auto scans = static_cast<double>(log->scans.size());
    state.counters["scans/s"] =
        benchmark::Counter(scans, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["iterations"] = iterations / (scans * static_cast<double>(state.iterations()));
}

}  // namespace

int main(int argc, char** argv) {
    if (std::any_of(argv + 1, argv + argc, [](const char* a) {
            return std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0;
        })) {
        std::cout << kHelp;
        return 0;
    }
    const std::string data = cli::takeOption(argc, argv, "--data", TOPOSLAM_SHARED_DATA_DIR);
    const std::string ini =
        cli::takeOption(argc, argv, "-c", TOPOSLAM_SOURCE_DIR "/config_ini/toposlam-slam.ini");
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 2;  // bad usage, as every TopoSLAM app
    mapping::GraphSlamOptions options;
    std::vector<SubmapLog> logs;
    try {
        if (!fs::is_regular_file(ini))
            throw io::InputError(ini, "no such file");
        options.loadFromConfigFile(mrpt::config::CConfigFile(ini), "GraphSlam");
        logs.push_back(
            readLog("office", TOPOSLAM_SOURCE_DIR "/share/office/office.rawlog", options));
        for (const auto& [name, relative] :
             {std::pair{"intel", "slam/intel.clf"}, std::pair{"fr079", "slam/fr079.clf"},
              std::pair{"simul", "rawlog/simul.rawlog"}}) {
            const fs::path path = fs::path(data) / relative;
            if (fs::exists(path))
                logs.push_back(readLog(name, path.string(), options));
            else
                std::cerr << "note: " << path.string() << " not found; " << name << " skipped\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    for (const SubmapLog& log : logs) {
        benchmark::RegisterBenchmark(("insert/" + log.name).c_str(), insert, &log, &options)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("icp/" + log.name).c_str(), icp, &log, &options)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
