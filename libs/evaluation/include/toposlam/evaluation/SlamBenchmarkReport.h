#pragma once
// The result of benchmark B3 (SlamBenchmark.h) for people, as a Markdown table with notes, and
// for scripts, as JSON (keys: share/doc/apps.md, toposlam-bench-slam).
#include <toposlam/evaluation/SlamBenchmark.h>
#include <nlohmann/json.hpp>

#include <string>

namespace toposlam::evaluation {

/// A few lines on the logs and the machine, then one table row per log and engine: relations
/// matched, translational and rotational error mean ± std, their squares, the maxima, the ATE
/// (ground-truth logs), wall and CPU time (s), real-time factor (log duration / wall time, and
/// / CPU time), peak RSS (MiB), loop closures (graph engine); then numbered notes for failed
/// and skipped runs and warnings.
std::string formatSlamBenchmarkTable(const SlamBenchmarkResult& result);

/// The whole result as JSON.
nlohmann::json slamBenchmarkJson(const SlamBenchmarkResult& result);

/// Writes slamBenchmarkJson() to `path` atomically.
void saveSlamBenchmarkJson(const SlamBenchmarkResult& result, const std::string& path);

}  // namespace toposlam::evaluation
