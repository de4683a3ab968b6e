// toposlam-bench-rooms: benchmark B4 (room segmentation) on the maps of Bormann et al. 2016 at
// any angle, B4-gen on generated furnished plans, and rooms on grids built by our own SLAM end
// to end; the virtual-door segmenter against the morphological and distance baselines in one
// run.
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/ImageMemoryReuse.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/cli/UsageError.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/roomsbench/GeneratedRoomCases.h>
#include <toposlam/roomsbench/RoomBenchmarkSuite.h>
#include <toposlam/simulation/FloorPlanGenerator.h>
#include <toposlam/simulation/FloorPlanImages.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Benchmark B4: room segmentation scored against ground-truth rooms and doors (metrics: "
    "shared/BENCHMARKS.md, B4) by the virtual-door segmenter (vdoor: TopoSLAM's default; "
    "vdoor-paper: the paper's method as published) and the morphological (morph) and "
    "distance-transform (dist) baselines of ipa_room_segmentation, on up to five sets:\n"
    "  bormann  the 20 maps of Bormann et al. (ICRA 2016), unfurnished and furnished;\n"
    "  gen      B4-gen: generated furnished office buildings with exact ground truth "
    "(--gen-seeds);\n"
    "  flats    B4-flats: generated furnished flats, rooms opening into rooms, no corridor "
    "(--flat-seeds);\n"
    "  rings    B4-rings: generated furnished buildings around a corridor ring, rows of rooms "
    "that look alike (--ring-seeds; not in the default --sets);\n"
    "  slam     end to end: a simulated robot tours generated plans and Bormann maps, "
    "toposlam's SLAM maps the log, the SLAM grid and trajectory are segmented and scored in "
    "the plan's frame (beside the same plans as drawn, set 'drawn'). Slow: minutes per plan.\n"
    "--rotations turns every bormann, gen, flats and rings map (and its ground truth) by each "
    "angle; "
    "--cell-size maps them in coarser cells. Prints "
    "one row per map and method, then the averages per set, method, furnishing and angle, and "
    "writes them as JSON. Every method runs single-threaded; times are wall-clock medians over "
    "--repeats runs of the segmentation call alone (loading excluded), with the thread's CPU "
    "time beside them.\nExamples:\n"
    "  toposlam-bench-rooms -o b4.json > b4.md\n"
    "  toposlam-bench-rooms --sets bormann,gen --rotations 0,10,17,30,45 -r 1 -o b4-rot.json\n"
    "  toposlam-bench-rooms --sets bormann --cell-size 0.1 -m vdoor -r 1 -o b4-10cm.json\n"
    "  toposlam-bench-rooms --sets slam -r 1 --images b4-slam-png -o b4-slam.json\n"
    "  toposlam-bench-rooms --sets rings -o b4-rings.json\n"
    "  toposlam-bench-rooms --write-plans gen-maps   # B4-gen and B4-flats as Bormann-format "
    "files";

std::vector<double> angleList(const std::string& text) {
    std::vector<double> angles;
    for (const std::string& item : cli::splitList(text))
        angles.push_back(cli::parseNumberList(item, 1, "--rotations",
                                              cli::NumberRange<double>::closed(-360, 360))
                             .front());
    return angles;
}

// B4-gen, B4-flats or B4-rings as files in Bormann's layout.
std::size_t writePlans(const std::string& dir, const std::vector<unsigned>& seeds,
                       const std::vector<double>& angles, simulation::BuildingStyle style) {
    simulation::FloorPlanGeneratorOptions options;
    options.style = style;
    for (const unsigned seed : seeds) {
        const auto plan = simulation::generateFloorPlan(seed, options);
        std::cout << roomsbench::generatedPlanName(seed, style) << ": " << plan.summary << "\n";
        for (const double angle : angles) {
            std::string name = roomsbench::generatedPlanName(seed, style);
            if (angle != 0)
                name += "_rot" + std::to_string(static_cast<int>(std::lround(angle)));
            simulation::saveFloorPlanImages(
                simulation::drawFloorPlan(plan, rooms::kBenchmarkMapResolution, angle), dir, name);
        }
    }
    return seeds.size() * angles.size();
}

struct Arguments {
    TCLAP::CmdLine cmd{kDescription, ' ', "0.2"};
    TCLAP::ValueArg<std::string> data{
        "d",
        "data",
        "folder with the Bormann maps (<map>.png, <map>_furnitures.png, "
        "<map>_gt_segmentation.png); default: " TOPOSLAM_SHARED_DATA_DIR "/rooms",
        false,
        TOPOSLAM_SHARED_DATA_DIR "/rooms",
        "dir",
        cmd};
    TCLAP::ValueArg<std::string> json{
        "o",    "json", "JSON output file (default: b4-rooms.json)", false, "b4-rooms.json",
        "file", cmd};
    TCLAP::ValueArg<std::string> images{
        "",
        "images",
        "write a PNG of every segmentation into this folder (<set>.<map>[@angle].<method>.png: "
        "segments coloured, true door pixels blue, virtual doors as 0.5 m circles: green = "
        "matched, red = not; vdoor also .steps.png)",
        false,
        "",
        "dir",
        cmd};
    cli::NumberArg<int> repeats{"r",
                                "repeats",
                                "runs per map and method; the median time is reported (default: 3)",
                                3,
                                cli::NumberRange<int>::positive(1000),
                                "n",
                                cmd};
    TCLAP::ValueArg<std::string> methods{
        "m",   "methods", "comma-separated subset of vdoor,vdoor-paper,morph,dist (default: all)",
        false, "",        "list",
        cmd};
    TCLAP::ValueArg<std::string> sets{
        "",
        "sets",
        "comma-separated subset of bormann,gen,flats,rings,slam (default: bormann,gen,flats)",
        false,
        "bormann,gen,flats",
        "list",
        cmd};
    TCLAP::ValueArg<std::string> maps{
        "",    "maps", "comma-separated subset of the 20 Bormann base map names (default: all)",
        false, "",     "list",
        cmd};
    TCLAP::ValueArg<std::string> rotations{
        "",
        "rotations",
        "comma-separated angles (deg, counter-clockwise) to turn every bormann, gen, flats and "
        "rings map by, "
        "nearest neighbour (default: 0)",
        false,
        "0",
        "list",
        cmd};
    cli::NumberArg<double> cellSize{
        "",
        "cell-size",
        "segment every bormann, gen, flats and rings map in cells of this size (m), scored in the "
        "drawn ground truth (default: 0 = as drawn). A whole multiple of the drawn 0.05 m: a cell "
        "is "
        "free when every drawn pixel in it is, as a laser grid marks a cell a beam ended in. A "
        "whole fraction of it (0.025, 0.0125): every pixel split into cells of its own state, as "
        "a finer grid shows the same walls",
        0.0,
        cli::NumberRange<double>::nonNegative(5),
        "m",
        cmd};
    TCLAP::ValueArg<std::string> genSeeds{
        "",    "gen-seeds", "B4-gen plans: seeds and ranges, e.g. 1-20 or 3,7 (default: 1-20)",
        false, "1-20",      "list",
        cmd};
    TCLAP::ValueArg<std::string> flatSeeds{
        "",    "flat-seeds", "B4-flats plans: seeds and ranges, e.g. 1-20 or 3,7 (default: 1-20)",
        false, "1-20",       "list",
        cmd};
    TCLAP::ValueArg<std::string> ringSeeds{
        "",    "ring-seeds", "B4-rings plans: seeds and ranges, e.g. 1-20 or 3,7 (default: 1-20)",
        false, "1-20",       "list",
        cmd};
    TCLAP::ValueArg<std::string> slamSeeds{
        "",     "slam-seeds", "end to end: generated plans to tour (default: 1-4)", false, "1-4",
        "list", cmd};
    TCLAP::ValueArg<std::string> slamRingSeeds{
        "",
        "slam-ring-seeds",
        "end to end: generated ring plans to tour (default: none)",
        false,
        "",
        "list",
        cmd};
    TCLAP::ValueArg<std::string> slamMaps{"",
                                          "slam-maps",
                                          "end to end: Bormann maps to tour, furnished (default: "
                                          "Freiburg52_scan,Freiburg79_scan,office_d)",
                                          false,
                                          "Freiburg52_scan,Freiburg79_scan,office_d",
                                          "list",
                                          cmd};
    TCLAP::ValueArg<std::string> slamConfig{
        "",
        "slam-config",
        "end to end: toposlam-slam's ini (default: " TOPOSLAM_SOURCE_DIR
        "/config_ini/toposlam-slam.ini)",
        false,
        TOPOSLAM_SOURCE_DIR "/config_ini/toposlam-slam.ini",
        "file.ini",
        cmd};
    TCLAP::ValueArg<std::string> simConfig{
        "",
        "sim-config",
        "end to end: toposlam-sim's ini for the tour, laser and odometry (default: "
        "toposlam-sim's built-in defaults, except that the tour also looks into every area "
        "it would leave unseen: [Tour] look_into_unseen = true, see config_ini/sim-office.ini)",
        false,
        "",
        "file.ini",
        cmd};
    TCLAP::ValueArg<std::string> workDir{
        "",    "work-dir",     "end to end: where the simulated logs go (default: b4-slam-logs)",
        false, "b4-slam-logs", "dir",
        cmd};
    TCLAP::ValueArg<std::string> writePlans{
        "",
        "write-plans",
        "write the B4-gen, B4-flats and B4-rings plans of --sets (--gen-seeds, --flat-seeds, "
        "--ring-seeds, at "
        "--rotations) into this folder in Bormann's format (<name>.png, _furnitures.png, "
        "_gt_segmentation.png, _doors.json) and exit",
        false,
        "",
        "dir",
        cmd};
    TCLAP::ValueArg<std::string> config{
        "c",
        "config",
        "ini file with a [RoomSegmenter] section for vdoor (see config_ini/rooms.ini; default: "
        "the built-in defaults); vdoor-paper runs the same options with every deviation off "
        "(as toposlam-rooms -c file --paper)",
        false,
        "",
        "file.ini",
        cmd};
};

roomsbench::RoomBenchmarkSuiteOptions suiteOptions(
    Arguments& a, std::unique_ptr<mrpt::config::CConfigFile>& slamIni) {
    roomsbench::RoomBenchmarkSuiteOptions o;
    o.bench.dataDir = a.data.getValue();
    o.bench.repeats = a.repeats.getValue();
    o.bench.imageDir = a.images.getValue();
    o.bench.methods = cli::splitList(a.methods.getValue());
    o.bench.maps = cli::splitList(a.maps.getValue());
    o.bench.rotationsDeg = angleList(a.rotations.getValue());
    o.bench.cellSize = a.cellSize.getValue();
    if (o.bench.cellSize > 0) {
        try {
            rooms::checkCellSize(o.bench.cellSize, rooms::kBenchmarkMapResolution);
        } catch (const std::invalid_argument& e) {
            throw cli::UsageError(std::string("--cell-size: ") + e.what());
        }
    }
    o.bench.virtualDoor = rooms::RoomSegmenter::Options::load(a.config.getValue(), false);
    o.bench.virtualDoorPaper = rooms::RoomSegmenter::Options::load(a.config.getValue(), true);
    const auto sets = cli::splitList(a.sets.getValue());
    auto has = [&](const char* s) { return std::find(sets.begin(), sets.end(), s) != sets.end(); };
    for (const auto& s : sets) {
        if (s != "bormann" && s != "gen" && s != "flats" && s != "rings" && s != "slam")
            throw cli::UsageError("--sets: unknown set '" + s +
                                  "' (bormann, gen, flats, rings, slam)");
    }
    const bool haveData = std::filesystem::is_directory(o.bench.dataDir);
    if (!haveData && (has("bormann") || has("slam")))
        std::cerr << "B4 skipped: the benchmark maps are not there (" << o.bench.dataDir
                  << "); get shared/data/rooms or pass --data\n";
    o.bormann = has("bormann") && haveData;
    if (has("gen"))
        o.generatedSeeds = cli::parseSeedList(a.genSeeds.getValue(), "--gen-seeds");
    if (has("flats"))
        o.flatSeeds = cli::parseSeedList(a.flatSeeds.getValue(), "--flat-seeds");
    if (has("rings"))
        o.ringSeeds = cli::parseSeedList(a.ringSeeds.getValue(), "--ring-seeds");
    if (has("slam")) {
        o.endToEndSeeds = cli::parseSeedList(a.slamSeeds.getValue(), "--slam-seeds");
        o.endToEndRingSeeds = cli::parseSeedList(a.slamRingSeeds.getValue(), "--slam-ring-seeds");
        if (haveData)
            o.endToEndBormannMaps = cli::splitList(a.slamMaps.getValue());
        slamIni = std::make_unique<mrpt::config::CConfigFile>(a.slamConfig.getValue());
        o.endToEnd.slamConfig = slamIni.get();
        if (!a.simConfig.getValue().empty())
            simulation::loadSimulatorConfig(mrpt::config::CConfigFile(a.simConfig.getValue()),
                                            o.endToEnd.simulator);
        o.endToEnd.workDir = a.workDir.getValue();
    }
    return o;
}

int run(int argc, char** argv) {
    Arguments a;
    if (const auto exitCode = cli::parseCommandLine(a.cmd, argc, argv))
        return *exitCode;
    for (const std::string& file : {a.config.getValue(), a.simConfig.getValue()}) {
        if (!file.empty() && !std::filesystem::is_regular_file(file))
            throw io::InputError(file, "no such config file");
    }
    if (!a.writePlans.getValue().empty()) {
        const auto sets = cli::splitList(a.sets.getValue());
        const auto has = [&](const char* s) {
            return std::find(sets.begin(), sets.end(), s) != sets.end();
        };
        const auto angles = angleList(a.rotations.getValue());
        std::size_t written = 0;
        if (has("gen"))
            written += writePlans(a.writePlans.getValue(),
                                  cli::parseSeedList(a.genSeeds.getValue(), "--gen-seeds"), angles,
                                  simulation::BuildingStyle::Office);
        if (has("flats"))
            written += writePlans(a.writePlans.getValue(),
                                  cli::parseSeedList(a.flatSeeds.getValue(), "--flat-seeds"),
                                  angles, simulation::BuildingStyle::Flat);
        if (has("rings"))
            written += writePlans(a.writePlans.getValue(),
                                  cli::parseSeedList(a.ringSeeds.getValue(), "--ring-seeds"),
                                  angles, simulation::BuildingStyle::Ring);
        std::cerr << "wrote " << written << " plans to " << a.writePlans.getValue() << "\n";
        return 0;
    }
    std::unique_ptr<mrpt::config::CConfigFile> slamIni;
    const auto options = suiteOptions(a, slamIni);
    if (!options.bormann && options.generatedSeeds.empty() && options.flatSeeds.empty() &&
        options.ringSeeds.empty() && options.endToEndSeeds.empty() &&
        options.endToEndBormannMaps.empty() && options.endToEndRingSeeds.empty()) {
        return 0;  // nothing left to run (the reason was printed)
    }
    io::ProgressDisplay progress("B4 room segmentation", "maps");
    const auto result = roomsbench::runRoomBenchmarkSuite(
        options, [&](double fraction, std::size_t done) { progress.update(fraction, done); });
    progress.finish();
    std::cout << roomsbench::suiteTable(result);
    io::saveTextFile(roomsbench::suiteJson(result, options), a.json.getValue());
    std::cerr << "wrote " << a.json.getValue() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    toposlam::cli::reuseFreedImageMemory();
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
