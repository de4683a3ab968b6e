#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/evaluation/LaserFrame.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/SlamEvaluationRun.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/MirrorImage.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace toposlam::evaluation {

TrajectoryToScore trajectoryToScore(TrajectorySource source, const std::string& spec,
                                    const std::string& defaultName) {
    const auto eq = spec.find('=');
    if (eq != std::string::npos && eq > 0 && spec.substr(0, eq).find('/') == std::string::npos)
        return {source, spec.substr(0, eq), spec.substr(eq + 1)};
    return {source, defaultName.empty() ? std::filesystem::path(spec).stem().string() : defaultName,
            spec};
}

namespace {
/// The last `parts` components of `file`'s path, the extension left out.
std::string pathTail(const std::string& file, std::size_t parts) {
    const std::filesystem::path path(file);
    std::vector<std::string> names = {path.stem().string()};
    for (auto p = path.parent_path(); names.size() < parts && !p.filename().empty();
         p = p.parent_path())
        names.push_back(p.filename().string());
    std::string tail;
    for (auto n = names.rbegin(); n != names.rend(); ++n)
        tail += (tail.empty() ? "" : "/") + *n;
    return tail;
}
}  // namespace

void nameRowsApart(std::vector<TrajectoryToScore>& rows) {
    std::map<std::string, std::vector<std::size_t>> byName;
    for (std::size_t i = 0; i < rows.size(); ++i)
        byName[rows[i].name].push_back(i);
    for (const auto& [name, group] : byName) {
        if (group.size() < 2)
            continue;
        // The shortest tail (up to the whole path) that tells the group's files apart.
        std::vector<std::string> tails(group.size());
        for (std::size_t parts = 1;; ++parts) {
            for (std::size_t k = 0; k < group.size(); ++k)
                tails[k] = pathTail(rows[group[k]].file, parts);
            const std::set<std::string> distinct(tails.begin(), tails.end());
            const bool longer = std::any_of(group.begin(), group.end(), [&](std::size_t i) {
                return pathTail(rows[i].file, parts + 1) != pathTail(rows[i].file, parts);
            });
            if (distinct.size() == group.size() || !longer)
                break;
        }
        std::map<std::string, int> seen;
        for (std::size_t k = 0; k < group.size(); ++k) {
            TrajectoryToScore& row = rows[group[k]];
            const bool fromFileName = name == std::filesystem::path(row.file).stem().string();
            std::string renamed = fromFileName ? tails[k] : name + " (" + tails[k] + ")";
            if (const int n = ++seen[renamed]; n > 1)  // the same file again
                renamed += " #" + std::to_string(n);
            row.name = renamed;
        }
    }
}

void SlamEvaluationRequest::validate() const {
    if (trajectories.empty()) {
        throw std::invalid_argument(
            "no trajectory to score (give a file, --trajectory, --odometry-of or "
            "--icp-slam-path)");
    }
    if (relationsFile.empty() == groundTruthFile.empty())
        throw std::invalid_argument("give exactly one of --relations and --ground-truth");
    const bool icpSlam = std::any_of(
        trajectories.begin(), trajectories.end(),
        [](const TrajectoryToScore& t) { return t.source == TrajectorySource::IcpSlamPath; });
    if (icpSlam && rawlog.empty())
        throw std::invalid_argument("--icp-slam-path needs --rawlog (the rawlog icp-slam ran on)");
    if (!icpSlam && !rawlog.empty())  // it would be read for nothing and ignored
        throw std::invalid_argument("--rawlog stamps --icp-slam-path lines, and none is given");
    if (!scanStamps.empty() && rawlog.empty())
        throw std::invalid_argument("--scan-stamps replaces the stamps of --rawlog's scans");
    if (!(stampTolerance >= 0) || !std::isfinite(stampTolerance))
        throw std::invalid_argument("--stamp-tolerance must be >= 0");
    if (!(groundTruthSeparation >= 0) || !std::isfinite(groundTruthSeparation))
        throw std::invalid_argument("--gt-separation must be >= 0");
    if (!std::isfinite(frameOffset))
        throw std::invalid_argument("--frame-offset must be finite");
}

namespace {

// Progress over several logs read one after another: log k of n covers [k/n, (k+1)/n).
class LogsProgress {
  public:
    LogsProgress(const io::ProgressCallback& progress, std::size_t logs)
        : progress_(progress), logs_(std::max<std::size_t>(logs, 1)) {}
    io::ProgressCallback nextLog() {
        const std::size_t k = started_++;
        if (!progress_)
            return {};
        return [this, k](double fraction, std::size_t scans) {
            progress_((static_cast<double>(k) + fraction) / static_cast<double>(logs_),
                      scansBefore_ + scans);
            scansInLog_ = scans;
        };
    }
    void logDone() {
        scansBefore_ += scansInLog_;
        scansInLog_ = 0;
    }

  private:
    const io::ProgressCallback& progress_;
    std::size_t logs_, started_ = 0, scansBefore_ = 0, scansInLog_ = 0;
};

void readReference(const SlamEvaluationRequest& request, SlamEvaluationRun& run) {
    SlamEvaluation& ev = run.evaluation;
    ev.stampTolerance = request.stampTolerance;
    ev.frameOffset = request.frameOffset;
    ev.referenceMirrored = request.mirrorReference;
    if (!request.relationsFile.empty()) {
        ev.referenceFile = request.relationsFile;
        run.relations = loadRelations(ev.referenceFile);
        ev.repeatedRelations = countRepeatedRelations(run.relations);
        if (request.mirrorReference)
            run.relations = mirroredRelations(run.relations);
    } else {
        ev.referenceFile = request.groundTruthFile;
        ev.referenceIsGroundTruth = true;
        run.groundTruth = io::loadTrajectory(ev.referenceFile);
        if (request.mirrorReference)
            run.groundTruth = io::mirroredTrajectory(*run.groundTruth);
        ev.groundTruthPoses = run.groundTruth->size();
        ev.groundTruthRelations.baseSeparation = request.groundTruthSeparation;
        run.relations = relationsFromGroundTruth(*run.groundTruth, ev.groundTruthRelations,
                                                 &ev.relationSeparations);
        if (run.relations.empty())
            throw io::InputError(ev.referenceFile, "fewer than 2 poses: no relation to score");
    }
    ev.relationCount = run.relations.size();
}

/// What each laser log says at its scans, read once however many options name the log
/// (--odometry-of X --mounting-from X --laser-frame-of X).
class LogScansCache {
  public:
    explicit LogScansCache(LogsProgress& progress) : progress_(progress) {}
    const LogScans& of(const std::string& log) {
        auto it = read_.find(log);
        if (it == read_.end()) {
            it = read_.emplace(log, readLogScans(log, progress_.nextLog())).first;
            progress_.logDone();
        }
        return it->second;
    }
    /// As odometryAtScans().
    const io::Trajectory2D& odometryOf(const std::string& log) {
        return evaluation::odometryOf(of(log), log);
    }

  private:
    LogsProgress& progress_;
    std::map<std::string, LogScans> read_;
};

io::Trajectory2D readTrajectory(const TrajectoryToScore& t, const SlamEvaluationRequest& request,
                                const std::vector<double>* stamps, LogScansCache& logs,
                                std::string& source) {
    source = t.file;
    switch (t.source) {
        case TrajectorySource::LogOdometry:
            source = "odometry of " + t.file;
            return logs.odometryOf(t.file);
        case TrajectorySource::IcpSlamPath:
            source = t.file + " + " + request.rawlog;
            return loadIcpSlamPath(t.file, request.rawlog, stamps);
        case TrajectorySource::TrajectoryFile:
            break;
    }
    return io::loadTrajectory(t.file);
}

}  // namespace

SlamEvaluationRun runSlamEvaluation(const SlamEvaluationRequest& request,
                                    const io::ProgressCallback& progress) {
    request.validate();
    SlamEvaluationRun run;
    readReference(request, run);
    SlamEvaluation& ev = run.evaluation;

    std::set<std::string> logsToRead;  // each read once
    for (const TrajectoryToScore& t : request.trajectories) {
        if (t.source == TrajectorySource::LogOdometry)
            logsToRead.insert(t.file);
    }
    for (const std::string* log :
         {&request.mountingLog, &request.scanStamps, &request.laserFrameLog}) {
        if (!log->empty())
            logsToRead.insert(*log);
    }
    LogsProgress logsProgress(progress, logsToRead.size());
    LogScansCache logs(logsProgress);
    std::optional<std::vector<double>> stamps;
    if (!request.scanStamps.empty()) {
        stamps.emplace();
        for (const io::TimedPose2D& scan : logs.of(request.scanStamps).laserPositions)
            stamps->push_back(scan.stamp);
    }
    const io::Trajectory2D* laserPositions = nullptr;  // in the cache, which outlives them
    if (!request.laserFrameLog.empty()) {
        laserPositions = &logs.of(request.laserFrameLog).laserPositions;
        ev.laserFrameLog = request.laserFrameLog;
        ev.laserPosition = typicalLaserPosition(*laserPositions);
    }
    const io::Trajectory2D* mountingOdometry = nullptr;
    if (!request.mountingLog.empty()) {
        ev.mountingLog = request.mountingLog;
        mountingOdometry = &logs.odometryOf(request.mountingLog);
    }
    const io::Trajectory2D* groundTruth = run.groundTruth ? &*run.groundTruth : nullptr;
    for (const TrajectoryToScore& t : request.trajectories) {
        std::string source;
        io::Trajectory2D estimate =
            readTrajectory(t, request, stamps ? &*stamps : nullptr, logs, source);
        if (estimate.empty())
            throw io::InputError(t.file, "no pose in the trajectory");
        std::optional<SensorMounting> mounting;
        if (mountingOdometry)
            mounting = estimateSensorMounting(*mountingOdometry, estimate, ev.stampTolerance);
        if (laserPositions)
            estimate = inLaserFrame(estimate, *laserPositions, ev.stampTolerance);
        for (io::TimedPose2D& p : estimate)  // the frame the relations were made in
            p.pose = poseAhead(p.pose, request.frameOffset);
        try {
            ev.methods.push_back(evaluateMethod(t.name, source, estimate, run.relations,
                                                groundTruth, ev.stampTolerance,
                                                groundTruth ? &ev.relationSeparations : nullptr));
        } catch (const std::invalid_argument& e) {
            throw io::InputError(t.file, e.what());
        }
        MethodEvaluation& m = ev.methods.back();
        m.mounting = mounting;
        m.worst = worstRelations(m.relative, run.relations, request.worstRelations);
        if (m.relative.matchedRelations == 0) {
            throw io::InputError(t.file,
                                 "matches none of the " + std::to_string(ev.relationCount) +
                                     " relations of " + ev.referenceFile +
                                     " (no pose within the stamp tolerance of a relation's stamps: "
                                     "another log, or stamps in another form?)");
        }
        if (request.keepEstimates)
            run.estimates.push_back(std::move(estimate));
    }
    return run;
}

void saveSlamEvaluationOutputs(const SlamEvaluationRun& run, const SlamEvaluationOutputs& out) {
    io::OutputGroup files;  // all that were asked for, or none
    if (!out.relations.empty())
        saveRelations(run.relations, out.relations);
    if (!out.plot.empty()) {
        saveEvaluationPlot(run.evaluation, run.estimates,
                           run.groundTruth ? &*run.groundTruth : nullptr, out.plot);
    }
    if (!out.json.empty())
        saveEvaluationJson(run.evaluation, out.json);
    files.commit();
}

}  // namespace toposlam::evaluation
