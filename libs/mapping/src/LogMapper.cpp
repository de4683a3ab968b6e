#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/system/datetime.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/mapping/GraphSlamInput.h>
#include <toposlam/mapping/IcpEngine.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/mapping/ManhattanAlignment.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace toposlam::mapping {

void SlamEngineOptions::declare(config::OptionsSchema& s) {
    s.choice<std::string>("engine", engine, {{"graph", "graph"}, {"icp", "icp"}},
                          "graph (TopoSLAM's graph SLAM) or icp (MRPT's icp-slam engine)");
    s.text("scan_label", scanLabel,
           "sensor label of the laser to map with (auto: the log's only or front laser)");
}

using mrpt::poses::CPose2D;

namespace {
/// [Slam]: SlamEngineOptions, which engine maps the log.
const char* const kEngineSection = "Slam";

/// Every record of one laser of the log (SlamEngineOptions::scanLabel), in order, to
/// `consume`; progress reported on the way; which laser, and what was left out, into `result`.
template <typename Consume>
void readLog(const std::string& logPath, const SlamEngineOptions& engine,
             const io::ProgressCallback& progress, MappingResult& result, Consume&& consume) {
    const bool automatic = engine.scanLabel == "auto";
    io::LaserLogOptions options;
    options.scanLabel = automatic ? std::string() : engine.scanLabel;
    options.oneLaser = automatic;
    io::LaserLogReader reader(logPath, options);
    io::LaserLogRecord record;
    std::size_t n = 0;
    while (reader.next(record)) {
        consume(record);
        ++n;
        if (progress)
            progress(reader.fractionRead(), n);
    }
    if (n == 0 && !automatic)
        throw io::InputError(logPath, reader.noScansProblem() + " ([Slam] scan_label)");
    result.laserLabel = reader.laserLabel();
    result.otherLaserScans = reader.otherLaserScans();
}

/// TopoSLAM's graph SLAM over the log; fills the poses of `scans` and the graph outputs.
void runGraphEngine(const std::string& logPath, const mrpt::config::CConfigFileBase& ini,
                    const SlamEngineOptions& engine, const io::ProgressCallback& progress,
                    std::vector<PosedScan>& scans, io::Trajectory2D& trajectory,
                    MappingResult& result) {
    GraphSlamInput input;
    input.loadFromConfigFile(ini);
    input.start();
    readLog(logPath, engine, progress, result, [&](const io::LaserLogRecord& record) {
        input.processObservation(record.odometryObservation());  // null (ignored) if none
        if (record.storedFeatures)  // an annotated rawlog: the engine reuses them
            input.processObservation(record.storedFeatures);
        input.processObservation(record.scan);
        trajectory.push_back({record.fileStamp, {}});
        scans.push_back({record.scan, {}});
    });
    input.finish();
    const GraphSlam& slam = input.slam();
    const std::vector<mrpt::poses::CPose2D> poses = slam.scanPoses();
    for (std::size_t i = 0; i < scans.size(); ++i) {
        scans[i].robotPose = poses[i];
        trajectory[i].pose = scans[i].robotPose.asTPose();
    }
    result.statistics = slam.statistics();
    result.guessFreeSearch = slam.options().globalSearchEvery > 0;
    result.smoothedScans = slam.options().smoothScans;
    result.odometryCalibration = slam.options().odometryCalibration.enabled;
    result.contestedLoops = slam.options().loopContestedSupport > 0;
    result.leverArmGate = slam.options().loopGateLeverArm;
    result.graph = slam.graph();
    input.getKeyframes(result.keyframes);
}

/// MRPT's ICP map builder (icp-slam's engine) over the log, loaded for it (IcpEngine.h).
void runIcpEngine(const std::string& logPath, const mrpt::config::CConfigFileBase& ini,
                  const SlamEngineOptions& engine, const io::ProgressCallback& progress,
                  std::vector<PosedScan>& scans, io::Trajectory2D& trajectory,
                  MappingResult& result) {
    const std::unique_ptr<IcpEngine> slam = loadIcpEngine(ini);
    readLog(logPath, engine, progress, result, [&](const io::LaserLogRecord& record) {
        const CPose2D pose = slam->process(record);
        trajectory.push_back({record.fileStamp, pose.asTPose()});
        scans.push_back({record.scan, pose});
    });
}

/// Turns every output about the map origin so the dominant walls run along the axes.
void alignWithWalls(const OccupancyGridOptions& options, std::vector<PosedScan>& scans,
                    MappingResult& result) {
    if (!options.alignWithWalls)
        return;
    const auto walls = estimateWallDirection(scans);
    if (!walls)
        return;
    result.wallDirectionStrength = walls->strength;
    if (walls->strength < options.minWallDirectionStrength)
        return;
    result.wallAlignment = -walls->angle;
    const CPose2D turn(0, 0, result.wallAlignment);
    for (std::size_t i = 0; i < scans.size(); ++i) {
        scans[i].robotPose = turn + scans[i].robotPose;
        result.trajectory[i].pose = scans[i].robotPose.asTPose();
    }
    if (result.graph)
        result.graph->transformNodes(turn);
    for (std::size_t i = 0; i < result.keyframes.size(); ++i)
        result.keyframes.getAsPair(i).pose->changeCoordinatesReference(mrpt::poses::CPose3D(turn));
}

/// A misspelt section ([GrahpSlam]) would otherwise be ignored without a word, leaving its
/// settings at their defaults. MRPT's map definitions ([MappingApplication_<map>_<NN>_<opts>],
/// read by engine = icp) are MRPT's to check.
void requireSlamSections(const mrpt::config::CConfigFileBase& ini) {
    std::vector<std::string> known = GraphSlamInput::configSections();
    known.insert(known.end(), {kEngineSection, IcpEngine::kMappingSection, IcpEngine::kIcpSection});
    std::vector<std::string> sections;
    ini.getAllSections(sections);
    for (const std::string& s : sections) {
        if (s.rfind("MappingApplication_", 0) == 0)
            known.push_back(s);
    }
    config::requireKnownSections(ini, known);
}

}  // namespace

MappingResult mapLog(const std::string& logPath, const mrpt::config::CConfigFileBase& ini,
                     const io::ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = io::processCpuSeconds();
    MappingResult result;
    requireSlamSections(ini);
    SlamEngineOptions engine;
    engine.loadFromConfigFile(ini, kEngineSection);
    result.engine = engine.engine;
    OccupancyGridOptions gridOptions;
    // The grid of the optimised poses has the builder's options, whichever engine ran.
    gridOptions.loadFromConfigFile(ini, GraphSlamInput::kGridSection);

    std::vector<PosedScan> scans;
    if (engine.engine == "graph")
        runGraphEngine(logPath, ini, engine, progress, scans, result.trajectory, result);
    else
        runIcpEngine(logPath, ini, engine, progress, scans, result.trajectory, result);
    if (scans.empty())
        throw io::InputError(logPath, "the log contains no laser scans");
    const bool anyReading = std::any_of(scans.begin(), scans.end(), [](const PosedScan& s) {
        for (std::size_t b = 0; b < s.scan->getScanSize(); ++b)
            if (s.scan->getScanRangeValidity(b))
                return true;
        return false;
    });
    if (!anyReading)
        throw io::InputError(logPath, "none of its " + std::to_string(scans.size()) +
                                          " laser scans has a valid reading");

    alignWithWalls(gridOptions, scans, result);
    result.scans = scans.size();
    if (!scans.empty())
        result.laserPosition = {scans.front().scan->sensorPose.x(),
                                scans.front().scan->sensorPose.y()};
    result.logDuration =
        mrpt::system::timeDifference(scans.front().scan->timestamp, scans.back().scan->timestamp);
    result.grid = buildOccupancyGrid(scans, gridOptions);
    result.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cpuSeconds = io::processCpuSeconds() - cpuStart;
    return result;
}

}  // namespace toposlam::mapping
