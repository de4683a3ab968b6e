#include <benchmark/benchmark.h>
#include <toposlam/featureeval/FeatureBenchmark.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/io/LaserLogReader.h>

#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

namespace toposlam::featureeval {

namespace fs = std::filesystem;

const std::vector<std::string>& benchmarkMethods() {
    static const std::vector<std::string> methods = {"corners", "corners-ls", "corners-paper",
                                                     "split-merge", "segments"};
    return methods;
}

namespace {

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

/// Times extractor.extract() per scan, cycling through the scans `get` returns.
template <class GetScan>
void registerTiming(const std::string& name, const std::string& method, std::size_t count,
                    GetScan get, const FeatureBenchmarkOptions& o) {
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
        ->Repetitions(o.repetitions)
        ->ReportAggregatesOnly(o.repetitions > 1)
        ->MinTime(o.minTime);
}

std::string sigmaName(double sigma) {
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << sigma;
    return s.str();
}

using Scans = std::vector<SimulatedScan>;
using Records = std::vector<io::LaserLogRecord>;

/// Accuracy of every method on every laser x noise level; the scans stay alive in `kept` for
/// the timings registered on them.
void simulatedPart(const FeatureBenchmarkOptions& o, FeatureBenchmarkReport& report,
                   std::vector<std::shared_ptr<Scans>>& kept, const io::ProgressCallback& progress,
                   std::size_t blocks) {
    const std::vector<LaserSetup> lasers = {
        {180, M_PI, 30}, {361, M_PI, 30}, {1081, 1.5 * M_PI, 30}};
    const std::vector<double> sigmas = {0.0, 0.01, 0.03};
    const auto scenes = makeScenes(o.rooms, o.seed);
    unsigned noiseSeed = o.seed * 1000;
    for (const auto& laser : lasers) {
        for (const double sigma : sigmas) {
            auto scans = std::make_shared<Scans>(simulateScans(scenes, laser, sigma, ++noiseSeed));
            kept.push_back(scans);
            for (const std::string& method : benchmarkMethods()) {
                SimulatedRow row;
                row.method = method;
                row.laser = laser.name();
                row.beams = laser.beams;
                row.sigma = sigma;
                row.scans = scans->size();
                auto extractor = features::makeFeatureExtractor(method);
                row.scores = scoreExtractor(*extractor, *scans);
                row.timingName = "B1/" + method + "/" + std::to_string(laser.beams) + "/sigma" +
                                 sigmaName(sigma);
                registerTiming(
                    row.timingName, method, scans->size(),
                    [scans](std::size_t i) -> const mrpt::obs::CObservation2DRangeScan& {
                        return (*scans)[i].scan;
                    },
                    o);
                report.simulated.push_back(row);
            }
            auto twoPoint = features::makeFeatureExtractor("corners");
            auto leastSquares = features::makeFeatureExtractor("corners-ls");
            report.agreements.push_back(
                {laser.name(), sigma, compareCorners(*twoPoint, *leastSquares, *scans)});
            if (progress) {
                const std::size_t done = kept.size();
                progress(double(done) / double(blocks), done);
            }
        }
    }
}

/// Features per scan of every method on one real log.
void realLogRows(const std::string& name, const std::shared_ptr<Records>& records,
                 const FeatureBenchmarkOptions& o, FeatureBenchmarkReport& report) {
    for (const std::string& method : benchmarkMethods()) {
        RealLogRow row;
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
            o);
        report.real.push_back(row);
    }
}

void realPart(const FeatureBenchmarkOptions& o, FeatureBenchmarkReport& report,
              std::vector<std::shared_ptr<Records>>& kept, const io::ProgressCallback& progress,
              std::size_t blocksBefore, std::size_t blocks) {
    std::size_t done = blocksBefore;
    for (const std::string name : {"intel", "fr079"}) {
        const fs::path path = fs::path(o.dataDir) / "slam" / (name + ".clf");
        if (fs::exists(path)) {
            auto records = std::make_shared<Records>(io::LaserLogReader::readAll(path));
            if (o.realScans > 0 && records->size() > o.realScans)
                records->resize(o.realScans);
            kept.push_back(records);
            realLogRows(name, records, o, report);
        } else {
            report.messages.push_back("skipped " + name + ".clf: not found at " + path.string());
        }
        if (progress) {
            ++done;
            progress(double(done) / double(blocks), done);
        }
    }
}

void runTimings(FeatureBenchmarkReport& report) {
    CapturingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::ClearRegisteredBenchmarks();
    const auto take = [&](const std::string& name, double& cpu, double& wall) {
        if (reporter.cpu.count(name)) {
            cpu = reporter.cpu[name];
            wall = reporter.wall[name];
        }
    };
    for (SimulatedRow& r : report.simulated)
        take(r.timingName, r.microseconds, r.wallMicroseconds);
    for (RealLogRow& r : report.real)
        take(r.timingName, r.microseconds, r.wallMicroseconds);
}

}  // namespace

FeatureBenchmarkReport runFeatureBenchmark(const FeatureBenchmarkOptions& options,
                                           const io::ProgressCallback& progress) {
    FeatureBenchmarkReport report;
    report.options = options;
    // Kept alive for the timings (the registered benchmarks refer to them).
    std::vector<std::shared_ptr<Scans>> datasets;
    std::vector<std::shared_ptr<Records>> logs;
    const std::size_t simulatedBlocks = 9, blocks = simulatedBlocks + (options.realLogs ? 2 : 0);
    simulatedPart(options, report, datasets, progress, blocks);
    if (options.realLogs)
        realPart(options, report, logs, progress, simulatedBlocks, blocks);
    runTimings(report);
    return report;
}

}  // namespace toposlam::featureeval
