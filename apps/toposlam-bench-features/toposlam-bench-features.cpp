// toposlam-bench-features: benchmark B1 (share/doc/benchmarks.md), corner and segment
// extraction. The benchmark is libs/featureeval's (FeatureBenchmark.h); this parses options,
// shows progress and writes the table (stdout) and the JSON file.
#include <benchmark/benchmark.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/featureeval/FeatureBenchmark.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/ProgressDisplay.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using namespace toposlam;

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

    featureeval::FeatureBenchmarkOptions options;
    options.rooms = rooms.getValue();
    options.seed = seed.getValue();
    options.dataDir = data.getValue();
    options.realLogs = !noReal.getValue();
    options.realScans = realScans.getValue();
    options.repetitions = repetitions.getValue();
    options.minTime = minTime.getValue();
    std::fprintf(stderr, "B1: %d rooms x 3 lasers x 3 noise levels%s, then timings\n",
                 options.rooms, options.realLogs ? ", intel and fr079" : "");
    io::ProgressDisplay progress("B1 accuracy", "blocks");
    const auto report = featureeval::runFeatureBenchmark(
        options, [&](double fraction, std::size_t done) { progress.update(fraction, done); });
    progress.finish();
    if (!help)
        benchmark::Shutdown();

    featureeval::printFeatureBenchmark(report, stdout);
    io::saveJsonFile(featureeval::featureBenchmarkJson(report), json.getValue());
    std::printf("\nwrote %s\n", json.getValue().c_str());
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
