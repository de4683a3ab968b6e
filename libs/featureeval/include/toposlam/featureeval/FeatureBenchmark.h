#pragma once
// Benchmark B1 (share/doc/benchmarks.md), corner and segment extraction, as a library: accuracy
// on simulated furnished rooms with exact ground truth per method x range noise x beam count;
// features per scan on every scan of the real logs intel and fr079; the median CPU time per
// scan of every method on the same scans with Google Benchmark (whose flags the caller passes
// to benchmark::Initialize first). toposlam-bench-features parses options and calls this.
#include <toposlam/featureeval/FeatureMetrics.h>
#include <toposlam/featureeval/SimulatedScans.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/ProgressCallback.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace toposlam::featureeval {

struct FeatureBenchmarkOptions {
    int rooms = 50;             ///< random rooms, 5 sensor poses each
    unsigned seed = 1;          ///< of rooms, poses and noise
    std::string dataDir;        ///< the public data (slam/intel.clf, slam/fr079.clf)
    bool realLogs = true;       ///< also the real logs (skipped with a message when absent)
    std::size_t realScans = 0;  ///< first N scans of each real log; 0 = all
    int repetitions = 5;        ///< Google Benchmark repetitions (the median is reported)
    double minTime = 0.05;      ///< s, minimum time of each repetition
};

/// One method on one simulated laser and noise level.
struct SimulatedRow {
    std::string method, laser;
    std::size_t beams = 0;
    double sigma = 0;
    FeatureScores scores;
    std::size_t scans = 0;
    double microseconds = NAN;      ///< median CPU time per scan
    double wallMicroseconds = NAN;  ///< median wall time per scan
    std::string timingName;         ///< its Google Benchmark name
};

/// One method on one real log.
struct RealLogRow {
    std::string method, log;
    std::size_t scans = 0, beams = 0;
    double segments = 0, corners = 0, endpoints = 0;  ///< per scan
    double microseconds = NAN, wallMicroseconds = NAN;
    std::string timingName;
};

/// Two-point fit vs least squares on the same simulated scans.
struct FitAgreement {
    std::string laser;
    double sigma = 0;
    CornerAgreement agreement;
};

struct FeatureBenchmarkReport {
    FeatureBenchmarkOptions options;
    std::vector<SimulatedRow> simulated;
    std::vector<FitAgreement> agreements;
    std::vector<RealLogRow> real;
    std::vector<std::string> messages;  ///< e.g. a real log that was not found
};

/// The methods compared (FeatureExtractor names).
const std::vector<std::string>& benchmarkMethods();

/// Runs B1. `progress`: over the accuracy part (laser x noise blocks, then real logs); the
/// timings follow (Google Benchmark prints its own table on stdout).
FeatureBenchmarkReport runFeatureBenchmark(const FeatureBenchmarkOptions& options,
                                           const io::ProgressCallback& progress = {});

/// The tables of share/doc/benchmarks.md and the targets, as Markdown.
void printFeatureBenchmark(const FeatureBenchmarkReport& report, std::FILE* out);
/// The report as JSON (every number, CPU and wall times).
io::Json featureBenchmarkJson(const FeatureBenchmarkReport& report);

}  // namespace toposlam::featureeval
