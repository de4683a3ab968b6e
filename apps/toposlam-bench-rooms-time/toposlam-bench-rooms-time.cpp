// toposlam-bench-rooms-time: how long the room segmentation takes per Bormann map (B4's time
// target), as a Google Benchmark: RoomSegmenter::segment (the defaults, `vdoor`; and the paper's
// method, `vdoor-paper`) on each of the 20 maps of Bormann et al., unfurnished and furnished,
// single-threaded, the map already loaded; and once per iteration over all 40 maps, whose
// counter cpu_ms_per_map is B4's "time per Bormann map" (CPU time of the calling thread).
// Data: --data <dir> (default ../shared/data/rooms); without it, nothing is timed.
#include <benchmark/benchmark.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/ImageMemoryReuse.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/io/InputError.h>
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace toposlam;

const char* const kHelp =
    "toposlam-bench-rooms-time: CPU time of the room segmentation (RoomSegmenter::segment) per "
    "Bormann map, single-threaded, map loaded beforehand (Google Benchmark).\n"
    "  vdoor/<map>, vdoor-paper/<map>  one map (20 maps, unfurnished and furnished)\n"
    "  vdoor/all-maps, vdoor-paper/all-maps  all 40 per iteration; counter cpu_ms_per_map = "
    "mean CPU time per map (B4's time target), ms_<stage> = mean wall time of each stage of "
    "RoomSegmenter::Result::stageMilliseconds per map\n"
    "Options: --data <dir>  Bormann's maps (default " TOPOSLAM_SHARED_DATA_DIR
    "/rooms)\n"
    "Google Benchmark flags are passed on, e.g. --benchmark_filter=all-maps "
    "--benchmark_repetitions=5 --benchmark_out=b4-time.json\n";

struct Map {
    std::string name;
    mrpt::maps::COccupancyGridMap2D grid;
};

void segmentOne(benchmark::State& state, const rooms::RoomSegmenter* segmenter, const Map* map) {
    for (auto _ : state) {
        auto result = segmenter->segment(map->grid, {}, map->name);
        benchmark::DoNotOptimize(result.map.labels.data);
    }
}

// "lines+directions" -> "lines_directions": counter names without spaces or operators.
std::string counterName(std::string stage) {
    std::replace_if(
        stage.begin(), stage.end(),
        [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return stage;
}

void segmentAll(benchmark::State& state, const rooms::RoomSegmenter* segmenter,
                const std::vector<Map>* maps) {
    double cpu = 0;
    std::map<std::string, double> stageMs;  // wall time per stage, summed over maps and iterations
    for (auto _ : state) {
        const double start = io::threadCpuSeconds();
        for (const Map& map : *maps) {
            auto result = segmenter->segment(map.grid, {}, map.name);
            benchmark::DoNotOptimize(result.map.labels.data);
            for (const auto& [stage, ms] : result.stageMilliseconds)
                stageMs[stage] += ms;
        }
        cpu += io::threadCpuSeconds() - start;
    }
    const double runs = static_cast<double>(state.iterations() * maps->size());
    state.counters["maps"] = static_cast<double>(maps->size());
    state.counters["cpu_ms_per_map"] = 1e3 * cpu / runs;
    for (const auto& [stage, ms] : stageMs)
        state.counters["ms_" + counterName(stage)] = ms / runs;
}

}  // namespace

int main(int argc, char** argv) {
    toposlam::cli::reuseFreedImageMemory();  // as toposlam-rooms: B4 times what users run
    if (std::any_of(argv + 1, argv + argc, [](const char* a) {
            return std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0;
        })) {
        std::cout << kHelp;
        return 0;
    }
    const std::string data =
        cli::takeOption(argc, argv, "--data", std::string(TOPOSLAM_SHARED_DATA_DIR) + "/rooms");
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 2;  // bad usage, as every TopoSLAM app
    if (!std::filesystem::is_directory(data)) {
        std::cerr << "error: " << data << ": no such folder; Bormann's maps are needed\n";
        return 1;
    }
    std::vector<Map> maps;
    try {
        for (const std::string& base : rooms::RoomBenchmark::benchmarkMaps()) {
            for (rooms::RoomBenchmarkCase& c : rooms::bormannCases(data, base, {0}))
                maps.push_back({c.name(), std::move(c.grid)});
        }
    } catch (const io::InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    cv::setNumThreads(1);  // B4 times every method single-threaded
    const rooms::RoomSegmenter improved(rooms::RoomSegmenter::Options::improved());
    const rooms::RoomSegmenter paper(rooms::RoomSegmenter::Options::paperExact());
    for (const auto& [method, segmenter] :
         {std::pair{"vdoor", &improved}, std::pair{"vdoor-paper", &paper}}) {
        benchmark::RegisterBenchmark((std::string(method) + "/all-maps").c_str(), segmentAll,
                                     segmenter, &maps)
            ->Unit(benchmark::kMillisecond);
        for (const Map& map : maps) {
            benchmark::RegisterBenchmark((std::string(method) + "/" + map.name).c_str(), segmentOne,
                                         segmenter, &map)
                ->Unit(benchmark::kMillisecond);
        }
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
