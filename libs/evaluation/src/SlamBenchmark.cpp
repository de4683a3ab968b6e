#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/LaserFrame.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/MapComparisonImage.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/SlamBenchmark.h>
#include <toposlam/evaluation/TrajectoryPlot.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/MirrorImage.h>

#include <stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace toposlam::evaluation {

namespace {

namespace fs = std::filesystem;

// The folder the runs work in: the one asked for (kept), or a fresh temporary one that is
// removed with everything in it when the benchmark ends.
class WorkDirectory {
  public:
    explicit WorkDirectory(const std::string& keep) : temporary_(keep.empty()) {
        if (temporary_) {
            std::string pattern =
                (fs::temp_directory_path() / "toposlam-bench-slam-XXXXXX").string();
            if (!::mkdtemp(pattern.data()))
                throw std::runtime_error(pattern + ": cannot create a temporary folder");
            path_ = pattern;
        } else {
            path_ = fs::absolute(keep);
            fs::create_directories(path_);
        }
    }
    ~WorkDirectory() {
        std::error_code ec;
        if (temporary_)
            fs::remove_all(path_, ec);
    }
    WorkDirectory(const WorkDirectory&) = delete;
    WorkDirectory& operator=(const WorkDirectory&) = delete;
    const fs::path& path() const { return path_; }
    bool temporary() const { return temporary_; }

  private:
    bool temporary_;
    fs::path path_;
};

// What a log is scored against.
struct Reference {
    PoseRelations relations;
    std::optional<io::Trajectory2D> groundTruth;
    std::vector<double> separations;  // ground truth: the scale of each derived relation
};

Reference loadReference(const SlamBenchmarkLog& log) {
    Reference reference;
    if (log.groundTruthFile.empty()) {
        reference.relations = loadRelations(log.relationsFile);
        return reference;
    }
    reference.groundTruth = io::loadTrajectory(log.groundTruthFile);
    reference.relations =
        relationsFromGroundTruth(*reference.groundTruth, {}, &reference.separations);
    if (reference.relations.empty())
        throw io::InputError(log.groundTruthFile, "fewer than 2 poses: no relation to score");
    return reference;
}

double loadAverage() {
    double load[1];
    return ::getloadavg(load, 1) == 1 ? load[0] : -1;
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string shortened(const std::string& text, std::size_t length) {
    return text.size() > length ? text.substr(0, length) + "..." : text;
}

// The row's map picture; `rotation` (rad) turns it into the frame of the first engine's.
MapPanel mapPanel(const SlamBenchmarkRow& row, double rotation) {
    MapPanel panel;
    panel.rotation = rotation;
    panel.title = engineName(row.run.engine);
    const SlamEngineRun& run = row.run;
    if (row.evaluation && row.evaluation->relative.matchedRelations > 0)
        panel.title += ": " + fixed(row.evaluation->relative.translation.mean, 4) + " m";
    if (run.status == SlamEngineRun::Status::Ok) {
        panel.title += ", " + fixed(run.process.cpuSeconds(), 1) + " s CPU";
        panel.imageFile = run.mapImage;
        panel.metresPerPixel = run.mapResolution;
        panel.missing = "no map picture";
    } else {
        panel.missing =
            std::string(run.status == SlamEngineRun::Status::Skipped ? "not run: " : "failed: ") +
            shortened(run.note, 70);
    }
    return panel;
}

}  // namespace

bool SlamBenchmarkResult::anyFailed() const {
    for (const SlamBenchmarkLogResult& log : logs) {
        if (!log.error.empty())
            return true;
        for (const SlamBenchmarkRow& row : log.rows) {
            if (row.run.status == SlamEngineRun::Status::Failed)
                return true;
        }
    }
    return false;
}

SlamBenchmark::SlamBenchmark(SlamBenchmarkOptions options) : options_(std::move(options)) {
    auto& engines = options_.engines;
    if (engines.empty())
        throw std::invalid_argument("no engine to run");
    for (auto e = engines.begin(); e != engines.end(); ++e) {
        if (std::find(e + 1, engines.end(), *e) != engines.end())
            throw std::invalid_argument(std::string("engine ") + engineName(*e) + " given twice");
    }
    const std::vector<SlamBenchmarkLog> found = findRelationLogs(options_.dataDir);
    const std::string missing = fs::is_directory(options_.dataDir)
                                    ? "no log with a .relations file in " + options_.dataDir
                                    : "the benchmark logs are not there (" + options_.dataDir + ")";
    std::vector<SlamBenchmarkLog> available = found;
    available.insert(available.end(), options_.simulatedLogs.begin(), options_.simulatedLogs.end());
    if (options_.logs.empty()) {
        if (found.empty())
            skipReason_ = missing;
        else
            logs_ = available;
        return;
    }
    std::string names;
    for (const SlamBenchmarkLog& log : available)
        names += (names.empty() ? "" : ", ") + log.name;
    for (const std::string& name : options_.logs) {
        const auto log = std::find_if(available.begin(), available.end(),
                                      [&](const SlamBenchmarkLog& l) { return l.name == name; });
        if (log == available.end() && found.empty()) {
            skipReason_ = missing;
            logs_.clear();
            return;
        }
        if (log == available.end())
            throw std::invalid_argument("no log '" + name + "' (there are: " + names + ")");
        if (std::count(options_.logs.begin(), options_.logs.end(), name) > 1)
            throw std::invalid_argument("log '" + name + "' given twice");
        logs_.push_back(*log);
    }
}

std::vector<std::pair<std::string, SlamEngine>> SlamBenchmark::runs() const {
    std::vector<std::pair<std::string, SlamEngine>> runs;
    for (const SlamBenchmarkLog& log : logs_) {
        for (const SlamEngine engine : options_.engines) {
            if (engine != SlamEngine::IcpSlam || !options_.setup.icpSlam.empty())
                runs.emplace_back(log.name, engine);
        }
    }
    return runs;
}

SlamBenchmarkResult SlamBenchmark::run(const io::ProgressCallback& progress) const {
    SlamBenchmarkResult result;
    result.cores = std::thread::hardware_concurrency();
    result.loadAverageBefore = loadAverage();
    const WorkDirectory work(options_.keepDir);
    if (!options_.imageDir.empty())
        fs::create_directories(options_.imageDir);
    const std::size_t total = runs().size();
    std::size_t done = 0;
    for (const SlamBenchmarkLog& log : logs_) {
        const fs::path logDirectory = work.path() / log.name;
        result.logs.push_back(runLog(log, logDirectory.string(), progress, done, total));
        if (work.temporary()) {  // the next log's runs need the disk space more
            std::error_code ec;
            fs::remove_all(logDirectory, ec);
        }
    }
    if (progress)
        progress(1.0, done);
    result.loadAverageAfter = loadAverage();
    if (!work.temporary())
        result.workDirectory = work.path().string();
    return result;
}

namespace {

// `log` as `alteration` changes it, converted into `directory` (io::convertLaserLog).
SlamBenchmarkLog altered(const SlamBenchmarkLog& log, const io::LogAlteration& alteration,
                         const fs::path& directory) {
    SlamBenchmarkLog out = log;
    if (alteration.keepEvery > 1)
        out.name += "-1in" + std::to_string(alteration.keepEvery);
    if (alteration.keepBeamEvery > 1)
        out.name += "-beams1in" + std::to_string(alteration.keepBeamEvery);
    if (alteration.clipRange > 0) {
        std::ostringstream range;
        range << alteration.clipRange;
        out.name += "-to" + range.str() + "m";
    }
    if (alteration.dropOdometry)
        out.name += "-laseronly";
    if (alteration.mirror)
        out.name += "-mirrored";
    fs::create_directories(directory);
    out.logFile = (directory / (out.name + ".rawlog")).string();
    io::LogConversionOptions conversion;
    conversion.rawlogPath = out.logFile;
    conversion.alteration = alteration;
    io::convertLaserLog(log.logFile, conversion);
    // The mirror image's reference is the reference's mirror image, written beside the log.
    if (alteration.mirror && !log.relationsFile.empty()) {
        out.relationsFile = (directory / (out.name + ".relations")).string();
        saveRelations(mirroredRelations(loadRelations(log.relationsFile)), out.relationsFile);
    } else if (alteration.mirror) {
        out.groundTruthFile = (directory / (out.name + "_gt.txt")).string();
        io::saveTrajectory(io::mirroredTrajectory(io::loadTrajectory(log.groundTruthFile)),
                           out.groundTruthFile);
    }
    return out;
}

}  // namespace

SlamBenchmarkLogResult SlamBenchmark::runLog(const SlamBenchmarkLog& recorded,
                                             const std::string& workDirectory,
                                             const io::ProgressCallback& progress,
                                             std::size_t& done, std::size_t total) const {
    SlamBenchmarkLogResult result;
    result.log = recorded;
    SlamBenchmarkLog log = recorded;
    const std::size_t runsOfLog = static_cast<std::size_t>(std::count_if(
        options_.engines.begin(), options_.engines.end(),
        [&](SlamEngine e) { return e != SlamEngine::IcpSlam || !options_.setup.icpSlam.empty(); }));
    Reference reference;
    io::Trajectory2D laserPositions;  // and the scans' stamps
    try {
        if (options_.alteration.any()) {
            log = altered(recorded, options_.alteration, workDirectory);
            result.log = log;
        }
        reference = loadReference(log);
        laserPositions = laserPositionsAtScans(log.logFile);
    } catch (const std::exception& e) {
        result.error = e.what();
        done += runsOfLog;
        return result;
    }
    std::vector<double> stamps;
    stamps.reserve(laserPositions.size());
    for (const io::TimedPose2D& scan : laserPositions)
        stamps.push_back(scan.stamp);
    // A ground truth gives the robot's poses; relation files are the laser's, unless told.
    if (!reference.groundTruth && !options_.robotFrame && laserOffCentre(laserPositions))
        result.laserPosition = typicalLaserPosition(laserPositions);
    result.scans = stamps.size();
    const auto [first, last] = std::minmax_element(stamps.begin(), stamps.end());
    result.durationSeconds = stamps.empty() ? 0.0 : *last - *first;
    result.relations = reference.relations.size();
    if (!reference.groundTruth)
        result.repeatedRelations = countRepeatedRelations(reference.relations);
    const io::Trajectory2D* groundTruth = reference.groundTruth ? &*reference.groundTruth : nullptr;
    for (const SlamEngine engine : options_.engines) {
        const bool startsProcess = engine != SlamEngine::IcpSlam || !options_.setup.icpSlam.empty();
        if (startsProcess && progress)
            progress(total ? double(done) / double(total) : 1.0, done);
        SlamBenchmarkRow row;
        row.run = runSlamEngine(engine, log, stamps, options_.setup,
                                (fs::path(workDirectory) / engineName(engine)).string());
        done += startsProcess ? 1 : 0;
        if (row.run.status == SlamEngineRun::Status::Ok) {
            try {
                row.evaluation = evaluateMethod(
                    engineName(engine), log.logFile,
                    result.laserPosition
                        ? inLaserFrame(row.run.trajectory, laserPositions, options_.stampTolerance)
                        : row.run.trajectory,
                    reference.relations, groundTruth, options_.stampTolerance,
                    groundTruth ? &reference.separations : nullptr);
            } catch (const std::exception& e) {
                row.run.status = SlamEngineRun::Status::Failed;
                row.run.note = std::string("trajectory not scored: ") + e.what();
            }
        }
        result.rows.push_back(std::move(row));
    }
    if (!options_.imageDir.empty()) {
        try {
            writeImages(result, groundTruth);
        } catch (const std::exception& e) {
            result.error = std::string("pictures not written: ") + e.what();
        }
    }
    return result;
}

void SlamBenchmark::writeImages(SlamBenchmarkLogResult& result,
                                const io::Trajectory2D* groundTruth) const {
    const fs::path directory(options_.imageDir);
    std::vector<MapPanel> panels;
    SlamEvaluation evaluation;
    evaluation.referenceFile =
        result.log.groundTruthFile.empty() ? result.log.relationsFile : result.log.groundTruthFile;
    evaluation.stampTolerance = options_.stampTolerance;
    std::vector<io::Trajectory2D> estimates;
    const io::Trajectory2D* frame = nullptr;  // the first scored engine's: all maps turned to it
    for (const SlamBenchmarkRow& row : result.rows) {
        if (!frame && row.evaluation)
            frame = &row.run.trajectory;
        const double rotation =
            frame && row.evaluation
                ? alignmentTo(*frame, row.run.trajectory, options_.stampTolerance).phi
                : 0.0;
        panels.push_back(mapPanel(row, rotation));
        if (row.evaluation) {
            evaluation.methods.push_back(*row.evaluation);
            estimates.push_back(row.run.trajectory);
        }
    }
    const std::string heading =
        "B3 " + result.log.name + " (" + std::to_string(result.scans) + " scans, " +
        fixed(result.durationSeconds, 0) +
        " s): each engine's occupancy grid, one scale, turned to the first one's frame";
    const fs::path maps = directory / (result.log.name + "-maps.png");
    saveMapComparison(panels, heading, maps.string());
    result.images.push_back(maps.string());
    if (!estimates.empty()) {
        const fs::path plot = directory / (result.log.name + "-trajectories.png");
        saveEvaluationPlot(evaluation, estimates, groundTruth, plot.string());
        result.images.push_back(plot.string());
    }
}

}  // namespace toposlam::evaluation
