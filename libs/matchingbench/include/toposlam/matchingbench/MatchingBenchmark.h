#pragma once
// Benchmark B2 (BENCHMARKS.md): every matcher on every pair of every set, in one process,
// once without a guess (all methods start from the identity: zero initial guess) and once
// with the pairs' odometry guess. Per method and set:
//   success     |ex|, |ey| < 0.1 m and |e_theta| < 0.03 rad (Li et al., Sensors 2016), with
//               e = estimate - truth component-wise; a method that declines (the graph
//               matcher's "no reliable match") fails the pair;
//   wrong       answered but not a success ("confident wrong pose", the graph matcher's
//               quality check should make this rare);
//   median translation / rotation error over all pairs (declined ones with their best pose);
//   median and 95th-percentile CPU time per pair.
// The table is printed (text, one row per method and set) and written as JSON.
#include <toposlam/matchingbench/PairMatcher.h>
#include <toposlam/matchingbench/ScanPair.h>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace toposlam::matchingbench {

struct MethodResult {
    std::string method, set, mode;  ///< mode: "zero-guess" or "odometry-guess"
    std::size_t pairs = 0, successes = 0, answered = 0, wrong = 0;
    double medianTranslationError = 0, medianRotationError = 0;  ///< m, rad
    double medianSeconds = 0, p95Seconds = 0, medianMatchSeconds = 0;
    double successRate() const { return pairs ? double(successes) / double(pairs) : 0.0; }
    double wrongRate() const { return pairs ? double(wrong) / double(pairs) : 0.0; }
};

struct BenchmarkReport {
    std::vector<MethodResult> results;
    void printTable(std::ostream& out) const;
    void writeJson(const std::string& path) const;  ///< atomic
};

/// Runs every method over `pairs` (grouped by pair.set, in order of first appearance) in
/// the given mode. `progress(done, total)` is called after each pair.
void runBenchmark(const ScanPairs& pairs, const std::vector<PairMatcher*>& methods,
                  bool useOdometryGuess, BenchmarkReport& report,
                  const std::function<void(std::size_t, std::size_t)>& progress = {});

/// True when the estimate is within the success tolerances of the truth.
bool isSuccess(const mrpt::poses::CPose2D& estimate, const mrpt::poses::CPose2D& truth);

}  // namespace toposlam::matchingbench
