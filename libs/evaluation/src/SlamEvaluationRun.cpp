#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/SlamEvaluationRun.h>
#include <toposlam/io/InputError.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace toposlam::evaluation {

TrajectoryToScore trajectoryToScore(TrajectorySource source, const std::string& spec,
                                    const std::string& defaultName) {
    const auto eq = spec.find('=');
    if (eq != std::string::npos && eq > 0 && spec.substr(0, eq).find('/') == std::string::npos)
        return {source, spec.substr(0, eq), spec.substr(eq + 1)};
    return {source, defaultName.empty() ? std::filesystem::path(spec).stem().string() : defaultName,
            spec};
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
    if (!request.relationsFile.empty()) {
        ev.referenceFile = request.relationsFile;
        run.relations = loadRelations(ev.referenceFile);
        ev.repeatedRelations = countRepeatedRelations(run.relations);
    } else {
        ev.referenceFile = request.groundTruthFile;
        ev.referenceIsGroundTruth = true;
        run.groundTruth = io::loadTrajectory(ev.referenceFile);
        ev.groundTruthPoses = run.groundTruth->size();
        ev.groundTruthRelations.baseSeparation = request.groundTruthSeparation;
        run.relations = relationsFromGroundTruth(*run.groundTruth, ev.groundTruthRelations,
                                                 &ev.relationSeparations);
        if (run.relations.empty())
            throw io::InputError(ev.referenceFile, "fewer than 2 poses: no relation to score");
    }
    ev.relationCount = run.relations.size();
}

io::Trajectory2D readTrajectory(const TrajectoryToScore& t, const SlamEvaluationRequest& request,
                                const std::vector<double>* stamps, LogsProgress& progress,
                                std::string& source) {
    source = t.file;
    switch (t.source) {
        case TrajectorySource::LogOdometry: {
            source = "odometry of " + t.file;
            auto odometry = odometryAtScans(t.file, progress.nextLog());
            progress.logDone();
            return odometry;
        }
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

    const auto logs = static_cast<std::size_t>(
        std::count_if(request.trajectories.begin(), request.trajectories.end(),
                      [](const auto& t) { return t.source == TrajectorySource::LogOdometry; }) +
        (request.scanStamps.empty() ? 0 : 1) + (request.mountingLog.empty() ? 0 : 1));
    LogsProgress logsProgress(progress, logs);
    std::optional<std::vector<double>> stamps;
    if (!request.scanStamps.empty()) {
        stamps = scanFileStamps(request.scanStamps, logsProgress.nextLog());
        logsProgress.logDone();
    }
    std::optional<io::Trajectory2D> mountingOdometry;
    if (!request.mountingLog.empty()) {
        ev.mountingLog = request.mountingLog;
        mountingOdometry = odometryAtScans(request.mountingLog, logsProgress.nextLog());
        logsProgress.logDone();
    }
    const io::Trajectory2D* groundTruth = run.groundTruth ? &*run.groundTruth : nullptr;
    for (const TrajectoryToScore& t : request.trajectories) {
        std::string source;
        io::Trajectory2D estimate =
            readTrajectory(t, request, stamps ? &*stamps : nullptr, logsProgress, source);
        if (estimate.empty())
            throw io::InputError(t.file, "no pose in the trajectory");
        std::optional<SensorMounting> mounting;
        if (mountingOdometry)
            mounting = estimateSensorMounting(*mountingOdometry, estimate, ev.stampTolerance);
        for (io::TimedPose2D& p : estimate) {  // the frame the relations were made in
            p.pose.x += request.frameOffset * std::cos(p.pose.phi);
            p.pose.y += request.frameOffset * std::sin(p.pose.phi);
        }
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
    if (!out.relations.empty())
        saveRelations(run.relations, out.relations);
    if (!out.plot.empty()) {
        saveEvaluationPlot(run.evaluation, run.estimates,
                           run.groundTruth ? &*run.groundTruth : nullptr, out.plot);
    }
    if (!out.json.empty())
        saveEvaluationJson(run.evaluation, out.json);
}

}  // namespace toposlam::evaluation
