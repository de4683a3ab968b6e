#pragma once
// Benchmark B3 in one run: every SLAM engine (SlamEngineRun.h) on every benchmark log
// (SlamBenchmarkLog.h), one run after the other so that timings do not compete, each scored
// with the relation metric of Kümmerle et al. 2009 (RelativePoseError.h) against the log's
// relation file, or against relations derived from a ground-truth trajectory together with
// the ATE (the simulated office). Reported per run: the errors, wall and CPU time, real-time
// factor, peak RSS, and the loop closures of TopoSLAM's graph engine (SlamBenchmarkReport.h).
#include <toposlam/evaluation/SlamEngineRun.h>
#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/ProgressCallback.h>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace toposlam::evaluation {

struct SlamBenchmarkOptions {
    /// Folder of the public logs: every `<name>.relations` with its log (findRelationLogs).
    std::string dataDir;
    /// Simulated logs scored against their ground truth (name, logFile, groundTruthFile),
    /// run after the public ones, e.g. share/office.
    std::vector<SlamBenchmarkLog> simulatedLogs;
    /// Log names to run, in this order (public and simulated); empty = all of them.
    std::vector<std::string> logs;
    /// Engines to run on every log, in this order (table rows).
    std::vector<SlamEngine> engines = {SlamEngine::Graph, SlamEngine::Icp, SlamEngine::IcpSlam};
    SlamEngineSetup setup;
    /// Keep every run's folder (configuration, outputs, stdout/stderr) under this folder; ""
    /// = a temporary folder, removed when the benchmark ends.
    std::string keepDir;
    /// Write `<log>-maps.png` (the engines' grids side by side) and `<log>-trajectories.png`
    /// (the trajectories aligned on one plot) into this folder; "" = none.
    std::string imageDir;
    double stampTolerance = StampedPoseLookup::kDefaultTolerance;
    /// Run every log as another robot would have recorded it (toposlam-convert --keep-every,
    /// --keep-beam-every, --clip-range, --no-odometry), named `<log>-1in<N>`,
    /// `<log>-beams1in<N>`, `<log>-to<R>m`, `<log>-laseronly`; scored on the reference's
    /// relations between kept scans. The default: the logs as recorded.
    io::LogAlteration alteration;
    /// Score relation logs as the robot's poses even where the log puts its laser off the
    /// robot's centre (relations made in the robot's frame); the default scores them at the
    /// laser (LaserFrame.h).
    bool robotFrame = false;
};

/// One table row: an engine on a log, and its score when it ran.
struct SlamBenchmarkRow {
    SlamEngineRun run;
    std::optional<MethodEvaluation> evaluation;
};

struct SlamBenchmarkLogResult {
    SlamBenchmarkLog log;
    std::size_t scans = 0;
    double durationSeconds = 0;         ///< last minus first scan stamp
    std::size_t relations = 0;          ///< relations scored (derived ones for a ground truth)
    std::size_t repeatedRelations = 0;  ///< of those, repeats of an earlier line of the file
    /// Relation files are made in the laser's frame (LaserFrame.h): where the log puts its
    /// laser off the robot's centre, every engine's poses were moved to it before scoring,
    /// and this is the laser's typical position on the robot (m, x forward, y left).
    std::optional<mrpt::math::TPoint2D> laserPosition;
    /// Set when the log or its reference could not be read (then no engine ran on it), or
    /// when its pictures could not be written.
    std::string error;
    std::vector<SlamBenchmarkRow> rows;
    std::vector<std::string> images;  ///< PNGs written for this log
};

struct SlamBenchmarkResult {
    std::vector<SlamBenchmarkLogResult> logs;
    std::string workDirectory;  ///< where the runs' folders are (kept only with keepDir)
    unsigned cores = 0;         ///< hardware threads of the machine
    double loadAverageBefore = -1, loadAverageAfter = -1;  ///< 1-minute load, -1 unknown
    /// A log could not be read or a run failed (skipped rows do not count).
    bool anyFailed() const;
};

class SlamBenchmark {
  public:
    /// Throws std::invalid_argument (a usage error) for an unknown or repeated log name in
    /// options.logs while options.dataDir is there, or for an empty or repeated engine list.
    explicit SlamBenchmark(SlamBenchmarkOptions options);

    /// Why nothing can be run ("" when it can): the data folder is absent (or holds no log
    /// with relations) and the selection needs it.
    const std::string& skipReason() const { return skipReason_; }
    /// The logs that will run, in order.
    const std::vector<SlamBenchmarkLog>& logs() const { return logs_; }
    /// (log name, engine) of every run that will start a process, in run order: what
    /// `progress` counts. icp-slam is left out when it is not installed (its rows are
    /// reported as skipped).
    std::vector<std::pair<std::string, SlamEngine>> runs() const;

    /// Runs everything; `progress` is called before each run with (runs done / runs, runs
    /// done) and once at the end. Failing runs are reported in their rows, unreadable logs and
    /// pictures in their log's result, not thrown. Throws std::runtime_error (or
    /// std::filesystem::filesystem_error) when the work or image folder cannot be created.
    SlamBenchmarkResult run(const io::ProgressCallback& progress = {}) const;

  private:
    /// `recorded`, or as options.alteration changes it (converted into workDirectory), run and
    /// scored.
    SlamBenchmarkLogResult runLog(const SlamBenchmarkLog& recorded,
                                  const std::string& workDirectory,
                                  const io::ProgressCallback& progress, std::size_t& done,
                                  std::size_t total) const;
    void writeImages(SlamBenchmarkLogResult& result, const io::Trajectory2D* groundTruth) const;

    SlamBenchmarkOptions options_;
    std::vector<SlamBenchmarkLog> logs_;
    std::string skipReason_;
};

}  // namespace toposlam::evaluation
