// toposlam-bench-io: how fast logs are read, TopoSLAM's LaserLogReader against MRPT's own
// readers on the same files (Google Benchmark; table on stdout, JSON with --benchmark_out).
//   TopoSLAM/<log>     LaserLogReader: every scan with its odometry (CARMEN or rawlog)
//   MRPT-carmen/<log>  mrpt::obs::carmen_log_parse_line, what carmen2rawlog runs
//   MRPT-CRawlog/<log> mrpt::obs::CRawlog::loadFromRawLogFile
// Data: --data <dir> (default ../shared/data): slam/intel.clf, slam/mit-csail.clf,
// rawlog/driving_in_office{,_obs}.rawlog, and intel converted to an observations rawlog
// (made once in a temporary directory). Missing files are skipped.
#include <benchmark/benchmark.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/carmen_log_tools.h>
#include <mrpt/system/datetime.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/LogConversion.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace toposlam;

void setScanCounters(benchmark::State& state, std::size_t scans) {
    state.counters["scans"] = static_cast<double>(scans);
    state.counters["scans/s"] = benchmark::Counter(static_cast<double>(scans),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void topoSlamReader(benchmark::State& state, const std::string& path) {
    std::size_t scans = 0;
    for (auto _ : state) {
        io::LaserLogReader reader(path);
        io::LaserLogRecord record;
        scans = 0;
        while (reader.next(record))
            ++scans;
        benchmark::DoNotOptimize(record.scan);
    }
    setScanCounters(state, scans);
}

void mrptCarmenImport(benchmark::State& state, const std::string& path) {
    std::size_t scans = 0;
    for (auto _ : state) {
        std::ifstream in(path);
        std::vector<mrpt::obs::CObservation::Ptr> observations;
        scans = 0;
        while (mrpt::obs::carmen_log_parse_line(in, observations, mrpt::system::now())) {
            for (const auto& o : observations) {
                if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o))
                    ++scans;
            }
        }
    }
    setScanCounters(state, scans);
}

void mrptRawlog(benchmark::State& state, const std::string& path) {
    std::size_t scans = 0;
    for (auto _ : state) {
        mrpt::obs::CRawlog rawlog;
        rawlog.loadFromRawLogFile(path);
        scans = 0;
        for (std::size_t i = 0; i < rawlog.size(); ++i) {
            const auto object = rawlog.getAsGeneric(i);
            if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(object))
                ++scans;
            if (const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
                scans += sf->size();
            }
        }
    }
    setScanCounters(state, scans);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string data = cli::takeOption(argc, argv, "--data", TOPOSLAM_SHARED_DATA_DIR);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 2;  // bad usage, as every TopoSLAM app

    const fs::path tmp =
        fs::temp_directory_path() / ("toposlam-bench-io-" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    const auto file = [&](const std::string& relative) {
        const fs::path p = fs::path(data) / relative;
        return fs::exists(p) ? p.string() : std::string();
    };
    for (const std::string name : {"intel", "mit-csail"}) {
        const std::string clf = file("slam/" + name + ".clf");
        if (clf.empty())
            continue;
        benchmark::RegisterBenchmark(("TopoSLAM/" + name + ".clf").c_str(), topoSlamReader, clf)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("MRPT-carmen/" + name + ".clf").c_str(), mrptCarmenImport,
                                     clf)
            ->Unit(benchmark::kMillisecond);
    }
    std::vector<std::string> rawlogs;
    if (const std::string intel = file("slam/intel.clf"); !intel.empty()) {
        io::LogConversionOptions options;
        options.rawlogPath = (tmp / "intel.rawlog").string();
        io::convertLaserLog(intel, options);
        rawlogs.push_back(options.rawlogPath);
    }
    for (const char* r :
         {"rawlog/driving_in_office.rawlog", "rawlog/driving_in_office_obs.rawlog"}) {
        if (const std::string p = file(r); !p.empty())
            rawlogs.push_back(p);
    }
    for (const std::string& r : rawlogs) {
        const std::string name = fs::path(r).filename().string();
        benchmark::RegisterBenchmark(("TopoSLAM/" + name).c_str(), topoSlamReader, r)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("MRPT-CRawlog/" + name).c_str(), mrptRawlog, r)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    fs::remove_all(tmp);
    return 0;
}
