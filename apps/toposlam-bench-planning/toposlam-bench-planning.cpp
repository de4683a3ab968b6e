// toposlam-bench-planning: benchmark B5, room-to-room planning on segmented maps. The
// benchmark itself is libs/planning/PlanningBenchmark.
#include <ompl/util/RandomNumbers.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/planning/PlanningBenchmark.h>
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace toposlam;
namespace fs = std::filesystem;

const char* const kDescription =
    "Benchmark B5: room-to-room planning. Each map is segmented into rooms (virtual doors, "
    "TopoSLAM defaults, no trajectory); for a fixed sample of room pairs, from anchor to "
    "anchor, it runs the room-graph planner (door route + OMPL per leg, toposlam-plan's "
    "method) and plain OMPL (same planner, the same total time budget), and compares both with "
    "the shortest 8-connected grid path (A*) on the same inflated grid. Prints one table "
    "(success rate, length / A*, ms per query) and writes JSON.\n"
    "Examples:\n"
    "  toposlam-bench-planning                                # share/office/office.gridmap.gz\n"
    "  toposlam-bench-planning --bormann ../shared/data/rooms --json b5.json";

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1.0");
    TCLAP::UnlabeledMultiArg<std::string> mapsArg(
        "maps", "grid maps (any supported format). Default: share/office/office.gridmap.gz", false,
        "map", cmd);
    TCLAP::ValueArg<std::string> bormannArg(
        "", "bormann",
        "also the 20 furnished maps of Bormann et al. from this folder (shared/data/rooms; "
        "0.05 m/px, grey < 250 = not free)",
        false, "", "dir", cmd);
    cli::NumberArg<double> freeThresholdArg(
        "", "free-threshold",
        "for the maps given as arguments: p(free) above which a cell is free. Default 0.6", 0.6,
        cli::NumberRange<double>::closed(0.5, 0.999), "p", cmd);
    cli::NumberArg<int> pairsArg("", "pairs", "room pairs per map (0 = all). Default 30", 30,
                                 cli::NumberRange<int>::nonNegative(1000000), "n", cmd);
    cli::NumberArg<double> radiusArg("", "robot-radius", "m. Default 0.25", 0.25,
                                     cli::NumberRange<double>::positive(10), "m", cmd);
    std::vector<std::string> planners = planning::omplPlannerNames();
    TCLAP::ValuesConstraint<std::string> plannerNames(planners);
    TCLAP::ValueArg<std::string> plannerArg("", "planner", "OMPL planner. Default rrtconnect",
                                            false, "rrtconnect", &plannerNames, cmd);
    cli::NumberArg<double> timeArg("", "time", "time limit per leg, s. Default 1", 1.0,
                                   cli::NumberRange<double>::positive(3600), "s", cmd);
    cli::NumberArg<int> attemptsArg(
        "", "attempts",
        "independent OMPL solves per leg, the shortest kept (RRT-Connect picks a random side "
        "of each obstacle). Default 3",
        3, cli::NumberRange<int>::positive(1000), "n", cmd);
    TCLAP::ValueArg<std::string> jsonArg("", "json", "write the results as JSON", false, "", "file",
                                         cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;
    ompl::RNG::setSeed(1);

    struct MapInput {
        std::string name, path;
        double freeThreshold;
    };
    std::vector<MapInput> maps;
    for (const auto& m : mapsArg.getValue())
        maps.push_back({fs::path(m).filename().string(), m, freeThresholdArg.getValue()});
    if (bormannArg.isSet()) {
        for (const auto& base : rooms::RoomBenchmark::benchmarkMaps()) {
            const std::string name = base + "_furnitures";
            maps.push_back({name, (fs::path(bormannArg.getValue()) / (name + ".png")).string(),
                            250.0 / 255.0});
        }
    }
    if (maps.empty()) {
        maps.push_back(
            {"office", std::string(TOPOSLAM_SOURCE_DIR) + "/share/office/office.gridmap.gz", 0.6});
    }

    planning::PlanningBenchmarkOptions options;
    options.robotRadius = radiusArg.getValue();
    options.ompl.planner = plannerArg.getValue();
    options.ompl.timeLimit = timeArg.getValue();
    options.ompl.attempts = attemptsArg.getValue();
    options.maxPairsPerMap = pairsArg.getValue();

    std::vector<planning::PlanningQuery> queries;
    io::ProgressDisplay progress("B5 planning", "maps");
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const auto grid = io::loadGridMap(maps[i].path);
        rooms::RoomSegmenter::Options segmentation;
        segmentation.freeSpace.freeThreshold = maps[i].freeThreshold;
        const auto segmented = rooms::RoomSegmenter(segmentation).segment(grid, {}, maps[i].path);
        options.freeThreshold = maps[i].freeThreshold;
        const auto q = planning::PlanningBenchmark(options).run(maps[i].name, grid, segmented.map);
        queries.insert(queries.end(), q.begin(), q.end());
        progress.update(static_cast<double>(i + 1) / static_cast<double>(maps.size()), i + 1);
    }
    progress.finish();

    const auto summary = planning::PlanningBenchmark::summarize(queries);
    std::printf("B5 room-to-room planning: %zu maps, robot radius %.2f m, %s, %.2f s per leg\n\n%s",
                maps.size(), options.robotRadius, options.ompl.planner.c_str(),
                options.ompl.timeLimit, planning::PlanningBenchmark::table(summary).c_str());
    if (jsonArg.isSet()) {
        io::saveTextFile(planning::PlanningBenchmark::json(queries, summary, options),
                         jsonArg.getValue());
        std::printf("\nwrote %s\n", jsonArg.getValue().c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
