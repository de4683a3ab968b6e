// toposlam-bench-rooms: benchmark B4 (room segmentation on the maps of Bormann et al. 2016),
// the virtual-door segmenter against the morphological and distance baselines in one run.
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/ProgressDisplay.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/rooms/RoomBenchmark.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace {

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty())
            out.push_back(item);
    }
    return out;
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Benchmark B4: room segmentation of the 20 maps of Bormann et al. (ICRA 2016), "
        "unfurnished and furnished, by the virtual-door segmenter (vdoor: TopoSLAM's "
        "default; vdoor-paper: the paper's method as published) and by the morphological "
        "(morph) and distance-transform (dist) baselines of ipa_room_segmentation. Prints "
        "one table per map and method, then the averages (unfurnished / furnished / all), "
        "and writes them as JSON. Metrics: shared/BENCHMARKS.md (B4). Every method runs "
        "single-threaded; times are wall-clock medians over --repeats runs of the "
        "segmentation call alone (map loading excluded).\nExample:\n"
        "  toposlam-bench-rooms -o b4.json --images b4-png > b4.md",
        ' ', "0.1");
    TCLAP::ValueArg<std::string> data(
        "d", "data",
        "folder with the Bormann maps (<map>.png, <map>_furnitures.png, "
        "<map>_gt_segmentation.png); default: " TOPOSLAM_SHARED_DATA_DIR "/rooms",
        false, TOPOSLAM_SHARED_DATA_DIR "/rooms", "dir", cmd);
    TCLAP::ValueArg<std::string> json("o", "json", "JSON output file (default: b4-rooms.json)",
                                      false, "b4-rooms.json", "file", cmd);
    TCLAP::ValueArg<std::string> images(
        "", "images",
        "write a PNG of every segmentation into this folder (segments coloured, "
        "true door pixels blue, virtual doors as 0.5 m circles: green = matched, red = not)",
        false, "", "dir", cmd);
    toposlam::cli::NumberArg<int> repeats(
        "r", "repeats", "runs per map and method; the median time is reported (default: 3)", 3,
        toposlam::cli::NumberRange<int>::positive(1000), "n", cmd);
    TCLAP::ValueArg<std::string> methods(
        "m", "methods", "comma-separated subset of vdoor,vdoor-paper,morph,dist (default: all)",
        false, "", "list", cmd);
    TCLAP::ValueArg<std::string> maps(
        "", "maps", "comma-separated subset of the 20 base map names (default: all)", false, "",
        "list", cmd);
    TCLAP::ValueArg<std::string> config(
        "c", "config",
        "ini file with a [RoomSegmenter] section for vdoor (see "
        "config_ini/rooms.ini; default: the built-in defaults); vdoor-paper always runs the "
        "paper-exact variant with that file's door width, area and Hough values",
        false, "", "file.ini", cmd);
    if (const auto exitCode = toposlam::cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    toposlam::rooms::RoomBenchmarkOptions options;
    options.dataDir = data.getValue();
    options.repeats = repeats.getValue();
    options.imageDir = images.getValue();
    options.methods = splitList(methods.getValue());
    options.maps = splitList(maps.getValue());
    if (!config.getValue().empty()) {
        if (!std::filesystem::exists(config.getValue())) {
            throw std::runtime_error(config.getValue() + ": no such config file");
        }
        const mrpt::config::CConfigFile ini(config.getValue());
        options.virtualDoor.loadFromConfigFile(ini, "RoomSegmenter");
        options.virtualDoorPaper = options.virtualDoor;
        const auto paper = toposlam::rooms::RoomSegmenter::Options::paperExact();
        options.virtualDoorPaper.door.localDirection = paper.door.localDirection;
        options.virtualDoorPaper.filters.keepNarrowestOfGroup = paper.filters.keepNarrowestOfGroup;
        options.virtualDoorPaper.filters.mergeSmallestFirst = paper.filters.mergeSmallestFirst;
        options.virtualDoorPaper.filters.requireWallJambs = paper.filters.requireWallJambs;
        options.virtualDoorPaper.filters.requireConstriction = paper.filters.requireConstriction;
    }
    if (!std::filesystem::is_directory(options.dataDir)) {
        std::cerr << "B4 skipped: the benchmark maps are not there (" << options.dataDir
                  << "); get shared/data/rooms or pass --data\n";
        return 0;
    }

    const toposlam::rooms::RoomBenchmark bench(options);
    toposlam::io::ProgressDisplay progress("B4 room segmentation", "maps");
    const auto scores = bench.run([&](std::size_t done, std::size_t total, const std::string&) {
        progress.update(static_cast<double>(done) / static_cast<double>(total), done);
    });
    progress.finish();
    const auto summary = toposlam::rooms::RoomBenchmark::summarize(scores);
    std::cout << toposlam::rooms::RoomBenchmark::table(scores, summary);
    toposlam::io::saveTextFile(toposlam::rooms::RoomBenchmark::json(scores, summary, options),
                               json.getValue());
    std::cerr << "wrote " << json.getValue() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
