// toposlam-bench-features: benchmark B1 (BENCHMARKS.md), corner and segment extraction.
// Accuracy on simulated furnished rooms with exact ground truth, per method x range noise x
// beam count; per-scan time with Google Benchmark on the same scans; features and time per
// scan on every scan of the real logs intel and fr079. One table on stdout, JSON to a file.
#include <benchmark/benchmark.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/featureeval/SimulatedScans.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/LaserLogReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace toposlam;
namespace fs = std::filesystem;

const char* const kDescription =
    "Benchmark B1: corner and segment extraction.\n"
    "Simulated part: random furnished polygonal rooms (rectangular/L-shaped rooms, 45-degree "
    "chamfers, boxes, triangles, round pillars), several sensor poses each, scanned exactly "
    "and with Gaussian range noise sigma = 0, 0.01, 0.03 m by lasers of 180 beams / 180 deg, "
    "361 / 180 deg and 1081 / 270 deg. Ground truth: visible polygon vertices with both walls "
    "observed (>= 5 beams each, incidence < 86 deg) and the visible extent of every wall. "
    "Per method: corner precision / recall (match within 0.10 m), corner position RMSE (all, "
    "and corners within 8 m), corner angle error, segment endpoint error (segments matched to "
    "visible walls by beam overlap), and the median time per scan (Google Benchmark, same "
    "scans, same process). Also: distance between the corners of the two-point and the "
    "least-squares fit.\n"
    "Real part: every scan of intel.clf and fr079.clf (../shared/data/slam; skipped with a "
    "message when absent): features and median time per scan.\n"
    "Methods: corners (corner paper, robust variant, two-point fit), corners-ls (least "
    "squares), corners-paper (the paper's rules as printed), split-merge (IEPF baseline), "
    "segments (convex/concave endpoints and segments, graph-matching paper sec. 2.1; no "
    "corners).\n"
    "Google Benchmark flags (--benchmark_filter, --benchmark_min_time, ...) are passed on; "
    "the filter only limits the timings.\n"
    "Example: toposlam-bench-features --json b1.json";

const std::vector<std::string> kMethods = {"corners", "corners-ls", "corners-paper", "split-merge",
                                           "segments"};

struct Row {
    std::string method, laser;
    std::size_t beams = 0;
    double sigma = 0;
    featureeval::FeatureScores scores;
    std::size_t scans = 0;
    double microseconds = NAN;  // median CPU time per scan
    double wallMicroseconds = NAN;
    std::string timingName;
};

struct RealRow {
    std::string method, log;
    std::size_t scans = 0, beams = 0;
    double segments = 0, corners = 0, endpoints = 0;  // per scan
    double microseconds = NAN;                        // median CPU time per scan
    double wallMicroseconds = NAN;
    std::string timingName;
};

/// Google Benchmark's console table, plus the median of every benchmark for our table. The
/// table quotes CPU time: on a shared machine wall time also counts the time other processes
/// hold the core (both are in the JSON).
class CapturingReporter : public benchmark::ConsoleReporter {
  public:
    std::map<std::string, double> cpu, wall;  // microseconds per scan
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
            const bool single = r.run_type == Run::RT_Iteration && r.repetitions <= 1;
            if (median || single) {
                cpu[r.run_name.function_name] = r.GetAdjustedCPUTime();
                wall[r.run_name.function_name] = r.GetAdjustedRealTime();
            }
        }
    }
};

/// Times extractor.extract() per scan, cycling through `scans`.
template <class GetScan>
void registerTiming(const std::string& name, const std::string& method, std::size_t count,
                    GetScan get, int repetitions, double minTime) {
    auto extractor = std::shared_ptr<features::FeatureExtractor>(
        features::makeFeatureExtractor(method).release());
    benchmark::RegisterBenchmark(
        name.c_str(),
        [extractor, count, get](benchmark::State& state) {
            features::ScanFeatures f;
            for (std::size_t i = 0; i < count; ++i)
                extractor->extract(get(i), f);  // warm up
            std::size_t i = 0;
            for (auto _ : state) {
                extractor->extract(get(i), f);
                benchmark::DoNotOptimize(f.segments.data());
                if (++i == count)
                    i = 0;
            }
            state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
        })
        ->Unit(benchmark::kMicrosecond)
        ->Repetitions(repetitions)
        ->ReportAggregatesOnly(repetitions > 1)
        ->MinTime(minTime);
}

std::string num(double v, int precision) {
    if (!std::isfinite(v))
        return "null";
    std::ostringstream s;
    s.precision(precision);
    s << std::fixed << v;
    return s.str();
}

std::string cell(double v, int precision) {
    return std::isfinite(v) ? num(v, precision) : "-";
}

int run(int argc, char** argv) {
    // Google Benchmark takes out the --benchmark_* flags, but would answer --help itself.
    const bool help = std::any_of(argv + 1, argv + argc, [](const char* a) {
        return std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0;
    });
    if (!help)
        benchmark::Initialize(&argc, argv);
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    cli::NumberArg<int> rooms("", "rooms", "Random rooms (5 sensor poses each). Default: 50", 50,
                              cli::NumberRange<int>::positive(100000), "N", cmd);
    cli::NumberArg<unsigned> seed("", "seed", "Seed of rooms, poses and noise. Default: 1", 1,
                                  cli::NumberRange<unsigned>::nonNegative(2147483647), "N", cmd);
    TCLAP::ValueArg<std::string> json("", "json", "JSON output file. Default: b1-features.json",
                                      false, "b1-features.json", "file", cmd);
    TCLAP::ValueArg<std::string> data(
        "", "data", "The public benchmark data folder. Default: ../shared/data of the build", false,
        TOPOSLAM_SHARED_DATA_DIR, "dir", cmd);
    cli::NumberArg<std::size_t> realScans(
        "", "real-scans", "Use only the first N scans of each real log. Default: 0 = all", 0,
        cli::NumberRange<std::size_t>::nonNegative(1000000000), "N", cmd);
    TCLAP::SwitchArg noReal("", "no-real", "Skip the real logs", cmd);
    cli::NumberArg<int> repetitions("", "repetitions",
                                    "Timing repetitions (the median is reported). Default: 5", 5,
                                    cli::NumberRange<int>::positive(1000), "N", cmd);
    cli::NumberArg<double> minTime("", "min-time",
                                   "Minimum time of each timing repetition, s. Default: 0.05", 0.05,
                                   cli::NumberRange<double>::positive(60), "s", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    // ---- Simulated scans and accuracy ------------------------------------------------------
    const std::vector<featureeval::LaserSetup> lasers = {
        {180, M_PI, 30}, {361, M_PI, 30}, {1081, 1.5 * M_PI, 30}};
    const std::vector<double> sigmas = {0.0, 0.01, 0.03};
    std::fprintf(stderr, "simulating %d rooms x %zu lasers x %zu noise levels...\n",
                 rooms.getValue(), lasers.size(), sigmas.size());
    const auto scenes = featureeval::makeScenes(rooms.getValue(), seed.getValue());
    // Kept alive for the timings (registered lambdas refer to them).
    std::vector<std::shared_ptr<std::vector<featureeval::SimulatedScan>>> datasets;
    std::vector<Row> rows;
    struct Agreement {
        std::string laser;
        double sigma;
        featureeval::CornerAgreement a;
    };
    std::vector<Agreement> agreements;
    unsigned noiseSeed = seed.getValue() * 1000;
    for (const auto& laser : lasers) {
        for (const double sigma : sigmas) {
            auto scans = std::make_shared<std::vector<featureeval::SimulatedScan>>(
                featureeval::simulateScans(scenes, laser, sigma, ++noiseSeed));
            datasets.push_back(scans);
            for (const std::string& method : kMethods) {
                Row row;
                row.method = method;
                row.laser = laser.name();
                row.beams = laser.beams;
                row.sigma = sigma;
                row.scans = scans->size();
                auto extractor = features::makeFeatureExtractor(method);
                row.scores = featureeval::scoreExtractor(*extractor, *scans);
                row.timingName =
                    "B1/" + method + "/" + std::to_string(laser.beams) + "/sigma" + num(sigma, 2);
                registerTiming(
                    row.timingName, method, scans->size(),
                    [scans](std::size_t i) -> const mrpt::obs::CObservation2DRangeScan& {
                        return (*scans)[i].scan;
                    },
                    repetitions.getValue(), minTime.getValue());
                rows.push_back(row);
            }
            auto twoPoint = features::makeFeatureExtractor("corners");
            auto leastSquares = features::makeFeatureExtractor("corners-ls");
            agreements.push_back({laser.name(), sigma,
                                  featureeval::compareCorners(*twoPoint, *leastSquares, *scans)});
        }
    }

    // ---- Real logs -------------------------------------------------------------------------
    std::vector<RealRow> realRows;
    std::vector<std::string> realMessages;
    std::vector<std::shared_ptr<std::vector<io::LaserLogRecord>>> logs;
    if (!noReal.getValue()) {
        for (const std::string name : {"intel", "fr079"}) {
            const fs::path path = fs::path(data.getValue()) / "slam" / (name + ".clf");
            if (!fs::exists(path)) {
                realMessages.push_back("skipped " + name + ".clf: not found at " + path.string());
                continue;
            }
            std::fprintf(stderr, "reading %s...\n", path.c_str());
            auto records = std::make_shared<std::vector<io::LaserLogRecord>>(
                io::LaserLogReader::readAll(path));
            if (realScans.getValue() > 0 && records->size() > realScans.getValue()) {
                records->resize(realScans.getValue());
            }
            logs.push_back(records);
            for (const std::string& method : kMethods) {
                RealRow row;
                row.method = method;
                row.log = name;
                row.scans = records->size();
                row.beams = records->empty() ? 0 : records->front().scan->getScanSize();
                auto extractor = features::makeFeatureExtractor(method);
                features::ScanFeatures f;
                for (const auto& r : *records) {
                    extractor->extract(*r.scan, f);
                    row.segments += static_cast<double>(f.segments.size());
                    row.corners += static_cast<double>(f.corners.size());
                    row.endpoints += static_cast<double>(f.endpoints.size());
                }
                const double n = std::max<double>(1, static_cast<double>(row.scans));
                row.segments /= n;
                row.corners /= n;
                row.endpoints /= n;
                row.timingName = "real/" + method + "/" + name;
                registerTiming(
                    row.timingName, method, records->size(),
                    [records](std::size_t i) -> const mrpt::obs::CObservation2DRangeScan& {
                        return *(*records)[i].scan;
                    },
                    repetitions.getValue(), minTime.getValue());
                realRows.push_back(row);
            }
        }
    }

    // ---- Timings ---------------------------------------------------------------------------
    std::fprintf(stderr, "timing (Google Benchmark, median of %d)...\n", repetitions.getValue());
    CapturingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    for (Row& r : rows) {
        if (reporter.cpu.count(r.timingName)) {
            r.microseconds = reporter.cpu[r.timingName];
            r.wallMicroseconds = reporter.wall[r.timingName];
        }
    }
    for (RealRow& r : realRows) {
        if (reporter.cpu.count(r.timingName)) {
            r.microseconds = reporter.cpu[r.timingName];
            r.wallMicroseconds = reporter.wall[r.timingName];
        }
    }
    const auto timeOf = [&](const std::string& method, std::size_t beams, double sigma) -> double {
        for (const Row& r : rows) {
            if (r.method == method && r.beams == beams && r.sigma == sigma)
                return r.microseconds;
        }
        return NAN;
    };

    // ---- Table -----------------------------------------------------------------------------
    std::printf("\nB1 simulated: %d rooms, %zu scans per laser and noise level (seed %u)\n\n",
                rooms.getValue(), rows.empty() ? std::size_t{0} : rows.front().scans,
                seed.getValue());
    std::printf(
        "| method | laser | sigma m | corner P | corner R | pos RMSE m | pos RMSE <= 8 m | angle "
        "err deg RMS / mean | seg endpoint RMSE m | walls matched | CPU us/scan | x split-merge |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row& r : rows) {
        const bool corners = r.method != "segments";
        const auto& s = r.scores;
        const double ratio = r.microseconds / timeOf("split-merge", r.beams, r.sigma);
        std::printf(
            "| %s | %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.method.c_str(),
            r.laser.c_str(), r.sigma,
            corners ? cell(100 * s.precision(), 1).append(" %").c_str() : "-",
            corners ? cell(100 * s.recall(), 1).append(" %").c_str() : "-",
            corners ? cell(s.positionRmse(), 4).c_str() : "-",
            corners ? cell(s.positionRmseNear(), 4).c_str() : "-",
            corners ? (cell(s.angleRmseDeg(), 2) + " / " + cell(s.angleMeanAbsDeg(), 2)).c_str()
                    : "-",
            cell(s.endpointRmse(), 4).c_str(), (cell(100 * s.segmentRecall(), 1) + " %").c_str(),
            cell(r.microseconds, 2).c_str(), cell(ratio, 2).c_str());
    }
    std::printf(
        "\nTwo-point fit vs least squares, same scans: distance between their corners\n\n"
        "| laser | sigma m | pairs | mean m | 95 %% m | max m |\n|---|---|---|---|---|---|\n");
    for (const auto& a : agreements) {
        std::printf("| %s | %.2f | %zu | %.4f | %.4f | %.4f |\n", a.laser.c_str(), a.sigma,
                    a.a.pairs, a.a.mean, a.a.p95, a.a.max);
    }
    if (!realRows.empty() || !realMessages.empty()) {
        std::printf(
            "\nB1 real logs: every scan\n\n"
            "| method | log | scans | beams | segments/scan | corners/scan | "
            "endpoints/scan | CPU us/scan | x split-merge |\n"
            "|---|---|---|---|---|---|---|---|---|\n");
        for (const RealRow& r : realRows) {
            double sm = NAN;
            for (const RealRow& o : realRows) {
                if (o.method == "split-merge" && o.log == r.log)
                    sm = o.microseconds;
            }
            std::printf("| %s | %s | %zu | %zu | %.1f | %.1f | %.1f | %s | %s |\n",
                        r.method.c_str(), r.log.c_str(), r.scans, r.beams, r.segments, r.corners,
                        r.endpoints, cell(r.microseconds, 2).c_str(),
                        cell(r.microseconds / sm, 2).c_str());
        }
        for (const std::string& m : realMessages)
            std::printf("%s\n", m.c_str());
    }

    // Targets of the corner extractor (issue 3).
    const Row* target = nullptr;
    for (const Row& r : rows) {
        if (r.method == "corners" && r.beams == 1081 && r.sigma == 0.01)
            target = &r;
    }
    if (target) {
        const auto& s = target->scores;
        const double t = target->microseconds, sm = timeOf("split-merge", 1081, 0.01);
        double worstAgreement = 0;
        for (const auto& a : agreements)
            worstAgreement = std::max(worstAgreement, a.a.mean);
        const auto mark = [](bool ok) { return ok ? "met" : "NOT met"; };
        std::printf(
            "\nTargets (corners, 1081 beams, sigma 0.01 m):\n"
            "  CPU time per scan %.2f us <= 20 us: %s; faster than split-merge (%.2f us): %s\n"
            "  recall %.1f %% >= 95 %%: %s; precision %.1f %% >= 95 %%: %s\n"
            "  position RMSE within 8 m %.4f m <= 0.02 m: %s; angle error %.2f deg RMS, "
            "%.2f deg mean <= 1 deg: %s (RMS), %s (mean)\n"
            "  two-point vs least squares: mean corner distance <= %.4f m <= 0.01 m: %s\n",
            t, mark(t <= 20), sm, mark(t < sm), 100 * s.recall(), mark(s.recall() >= 0.95),
            100 * s.precision(), mark(s.precision() >= 0.95), s.positionRmseNear(),
            mark(s.positionRmseNear() <= 0.02), s.angleRmseDeg(), s.angleMeanAbsDeg(),
            mark(s.angleRmseDeg() <= 1), mark(s.angleMeanAbsDeg() <= 1), worstAgreement,
            mark(worstAgreement <= 0.01));
    }

    // ---- JSON ------------------------------------------------------------------------------
    const auto rounded = [](double v, int decimals) { return io::roundDecimals(v, decimals); };
    io::Json simulated = io::Json::array(), agreement = io::Json::array(), real = io::Json::array();
    for (const Row& r : rows) {
        const auto& s = r.scores;
        simulated.push_back({{"method", r.method},
                             {"beams", r.beams},
                             {"laser", r.laser},
                             {"sigma", r.sigma},
                             {"scans", r.scans},
                             {"ground_truth_corners", s.groundTruthCorners},
                             {"detected_corners", s.detectedCorners},
                             {"ignored", s.ignored},
                             {"hits", s.hits},
                             {"precision", rounded(s.precision(), 4)},
                             {"recall", rounded(s.recall(), 4)},
                             {"position_rmse_m", rounded(s.positionRmse(), 5)},
                             {"position_rmse_within_8m_m", rounded(s.positionRmseNear(), 5)},
                             {"angle_rmse_deg", rounded(s.angleRmseDeg(), 3)},
                             {"angle_mean_abs_deg", rounded(s.angleMeanAbsDeg(), 3)},
                             {"segment_endpoint_rmse_m", rounded(s.endpointRmse(), 5)},
                             {"walls", s.groundTruthRuns},
                             {"walls_matched", s.matchedRuns},
                             {"cpu_us_per_scan", rounded(r.microseconds, 3)},
                             {"wall_us_per_scan", rounded(r.wallMicroseconds, 3)}});
    }
    for (const auto& a : agreements) {
        agreement.push_back({{"laser", a.laser},
                             {"sigma", a.sigma},
                             {"pairs", a.a.pairs},
                             {"mean_m", rounded(a.a.mean, 5)},
                             {"p95_m", rounded(a.a.p95, 5)},
                             {"max_m", rounded(a.a.max, 5)}});
    }
    for (const RealRow& r : realRows) {
        real.push_back({{"method", r.method},
                        {"log", r.log},
                        {"scans", r.scans},
                        {"beams", r.beams},
                        {"segments_per_scan", rounded(r.segments, 3)},
                        {"corners_per_scan", rounded(r.corners, 3)},
                        {"endpoints_per_scan", rounded(r.endpoints, 3)},
                        {"cpu_us_per_scan", rounded(r.microseconds, 3)},
                        {"wall_us_per_scan", rounded(r.wallMicroseconds, 3)}});
    }
    io::saveJsonFile({{"benchmark", "B1"},
                      {"rooms", rooms.getValue()},
                      {"seed", seed.getValue()},
                      {"simulated", simulated},
                      {"two_point_vs_least_squares", agreement},
                      {"real", real}},
                     json.getValue());
    std::printf("\nwrote %s\n", json.getValue().c_str());
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
