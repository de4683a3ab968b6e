#pragma once
// The result of benchmark B3 (SlamBenchmark.h) for people, as a Markdown table with notes, and
// for scripts, as JSON (keys: share/doc/apps.md, toposlam-bench-slam).
#include <toposlam/evaluation/SlamBenchmark.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace toposlam::evaluation {

/// How one engine did on the logs of one group (a simulated robot, SlamBenchmarkLog::group),
/// over every plan and seed: one tour's outcome is partly chance (a loop found or missed), so
/// the spread and the worst log say as much as the mean.
struct SlamGroupSummary {
    std::string group;
    SlamEngine engine = SlamEngine::Graph;
    std::size_t logs = 0;    ///< logs of the group in the run
    std::size_t failed = 0;  ///< of those, runs that failed (not scored)
    ErrorStatistics ate;     ///< ATE RMSE (m) of the scored logs
    double ateMedian = 0;    ///< m
    std::string worstLog;    ///< the log of the largest ATE RMSE
    /// Mean of the scored logs' mean translational relation errors (m).
    double translationMean = 0;
};

/// One summary per group and engine, groups in the order their first log ran, engines in
/// row order; empty when no log has a group.
std::vector<SlamGroupSummary> summariseByGroup(const SlamBenchmarkResult& result);

/// A few lines on the logs and the machine, then one table row per log and engine: relations
/// matched, translational and rotational error mean ± std, their squares, the maxima, the ATE
/// (ground-truth logs), wall and CPU time (s), real-time factor (log duration / wall time, and
/// / CPU time), peak RSS (MiB), loop closures (graph engine); then numbered notes for failed
/// and skipped runs and warnings; then, when logs have groups, a table of summariseByGroup().
std::string formatSlamBenchmarkTable(const SlamBenchmarkResult& result);

/// The whole result as JSON.
nlohmann::json slamBenchmarkJson(const SlamBenchmarkResult& result);

/// Writes slamBenchmarkJson() to `path` atomically.
void saveSlamBenchmarkJson(const SlamBenchmarkResult& result, const std::string& path);

}  // namespace toposlam::evaluation
