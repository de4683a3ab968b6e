// toposlam-bench-matching: benchmark B2 (BENCHMARKS.md). The graph matcher and MRPT's CICP
// (classic and Levenberg-Marquardt) side by side on the same scan pairs, in one run:
// simulated pairs (exact truth) and the intel / mit-csail relation pairs, first with zero
// initial guess, then with the odometry guess. Prints one table, writes JSON.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/matchingbench/MatchingBenchmark.h>
#include <toposlam/matchingbench/RelationPairs.h>
#include <toposlam/matchingbench/SimulatedPairs.h>
#include <toposlam/mrptslam/CGraphMatcherAlignment.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

using namespace toposlam;

namespace {
void run(const matchingbench::ScanPairs& pairs,
         const std::vector<matchingbench::PairMatcher*>& methods, bool guess,
         const std::string& what, matchingbench::BenchmarkReport& report) {
    io::ProgressDisplay progress(what, "pairs");
    matchingbench::runBenchmark(pairs, methods, guess, report,
                                [&](std::size_t done, std::size_t total) {
                                    progress.update(double(done) / double(total), done);
                                });
    progress.finish();
}
/// The options of the compared matchers: defaults, or read from an .ini file.
struct MatcherOptions {
    std::unique_ptr<mrpt::config::CConfigFile> ini;  ///< for the extractors' sections
    matching::GraphMatcherOptions graph;
    mrpt::slam::CICP::TConfigParams icp;
};

MatcherOptions matcherOptions(const std::string& iniPath) {
    MatcherOptions o;
    // Defaults = peers/icp-slam-benchmark.ini's [ICP] (the icp-slam peer of B3).
    o.icp.maxIterations = 80;
    o.icp.minAbsStep_trans = 1e-6f;
    o.icp.minAbsStep_rot = 1e-6f;
    o.icp.thresholdDist = 0.5f;
    o.icp.thresholdAng = 0.15f * float(M_PI / 180.0);
    o.icp.ALFA = 0.8f;
    o.icp.smallestThresholdDist = 0.05f;
    o.icp.onlyUniqueRobust = true;
    o.icp.corresponding_points_decimation = 1;
    if (iniPath.empty())
        return o;
    o.ini = toposlam::config::openIniFile(iniPath);
    // The section CGraphMatcherAlignment reads (graph-matcher.ini); its two keys of the MRPT
    // interface do not apply to the benchmark, which calls the matcher directly.
    mrptslam::CGraphMatcherAlignment::Options alignment;
    alignment.loadFromConfigFile(*o.ini, "GraphScanMatcher");
    o.graph = alignment.matcher;
    o.icp.loadFromConfigFile(*o.ini, "ICP");
    return o;
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Benchmark B2: graph scan matcher vs MRPT CICP (classic, Levenberg-Marquardt) on "
        "simulated and real (relation file) scan pairs; zero initial guess, then odometry "
        "guess. Success: |ex|,|ey| < 0.1 m and |etheta| < 0.03 rad. Times: CPU time per pair "
        "from the two raw scans (graph: feature extraction + matching).",
        ' ', "0.1");
    TCLAP::ValueArg<std::string> data("d", "data",
                                      "folder with slam/<log>.clf and slam/<log>.relations "
                                      "(default: ../shared/data of the source tree)",
                                      false, TOPOSLAM_SHARED_DATA_DIR, "dir", cmd);
    TCLAP::ValueArg<std::string> logs("l", "logs", "real logs to use (default intel,mit-csail)",
                                      false, "intel,mit-csail", "names", cmd);
    TCLAP::ValueArg<std::string> config(
        "c", "config",
        "ini with [GraphScanMatcher] (matcher options), the extractors' sections "
        "([SplitAndMergeExtractor], [CornerExtractor], [SegmentExtractor]) and [ICP] (CICP "
        "options for both CICP variants; ICP_algorithm is overridden). Default: built-in "
        "defaults (config_ini/graph-matcher.ini, features.ini, bench-matching-icp.ini)",
        false, "", "file.ini", cmd);
    TCLAP::ValueArg<std::string> extractors(
        "e", "extractors",
        "feature extractors of the graph-matcher rows (default split-merge,corners,segments: "
        "IEPF lines, the corner paper's segments, the graph paper's sec. 2.1 convex/concave "
        "segments)",
        false, "split-merge,corners,segments", "names", cmd);
    cli::NumberArg<std::size_t> simPairs("s", "sim-pairs",
                                         "simulated pairs per room x offset x rotation "
                                         "(2 x 4 x 4 cases; default 10, 0 = none)",
                                         10, cli::NumberRange<std::size_t>::nonNegative(100000),
                                         "n", cmd);
    cli::NumberArg<std::size_t> maxReal(
        "m", "max-real-pairs", "relations used per log, evenly spaced (default 0 = all)", 0,
        cli::NumberRange<std::size_t>::nonNegative(1000000000), "n", cmd);
    TCLAP::SwitchArg noGuess("", "no-guess-run", "skip the odometry-guess run", cmd);
    TCLAP::ValueArg<std::string> json("j", "json", "JSON output (default bench-matching.json)",
                                      false, "bench-matching.json", "file", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    const MatcherOptions o = matcherOptions(config.isSet() ? config.getValue() : "");
    const matching::GraphMatcherOptions& graphOptions = o.graph;
    const mrpt::slam::CICP::TConfigParams& icpParams = o.icp;
    const auto& ini = o.ini;

    std::vector<std::unique_ptr<matchingbench::PairMatcher>> owned;
    for (const std::string& e : cli::splitList(extractors.getValue()))
        owned.push_back(std::make_unique<matchingbench::GraphPairMatcher>("graph (" + e + ")", e,
                                                                          graphOptions, ini.get()));
    auto classic = icpParams, lm = icpParams;
    classic.ICP_algorithm = mrpt::slam::icpClassic;
    lm.ICP_algorithm = mrpt::slam::icpLevenbergMarquardt;
    owned.push_back(std::make_unique<matchingbench::CicpPairMatcher>("CICP classic", classic));
    owned.push_back(std::make_unique<matchingbench::CicpPairMatcher>("CICP LM", lm));
    std::vector<matchingbench::PairMatcher*> methods;
    for (auto& m : owned)
        methods.push_back(m.get());

    matchingbench::ScanPairs pairs;
    if (simPairs.getValue() > 0) {
        matchingbench::SimulatedPairsOptions so;
        so.pairsPerCase = simPairs.getValue();
        pairs = matchingbench::makeSimulatedPairs(so);
    }
    for (const std::string& log : cli::splitList(logs.getValue())) {
        const std::string base = data.getValue() + "/slam/" + log;
        auto real = matchingbench::loadRelationPairs(base + ".clf", base + ".relations", log,
                                                     maxReal.getValue());
        pairs.insert(pairs.end(), real.begin(), real.end());
    }
    if (pairs.empty())
        throw std::runtime_error("no pairs: give --sim-pairs > 0 or --logs");

    matchingbench::BenchmarkReport report;
    run(pairs, methods, false, "zero guess", report);
    if (!noGuess.getValue())
        run(pairs, methods, true, "odometry guess", report);
    report.printTable(std::cout);
    report.writeJson(json.getValue());
    std::cout << "JSON: " << json.getValue() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
