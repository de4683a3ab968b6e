// toposlam-rooms: room segmentation of an occupancy grid by virtual-door detection, written as
// a topological map (rooms = nodes, doors = edges) in JSON, GraphML, PNG and MRPT formats.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/ImageMemoryReuse.h>
#include <toposlam/cli/MapReadingArgs.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/rooms/RoomSegmentationJob.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace toposlam;

const char* const kDescription =
    "Cuts an occupancy grid into rooms at virtual doors (Qi et al. 2020: binarise, wall "
    "segments by probabilistic Hough, main directions, door search along them from the robot's "
    "trajectory, distance / adjacency / minimum-area filters, connected components) and writes "
    "the topological map: rooms are nodes, doors are edges.\n"
    "Input: a grid map (.gridmap, .gridmap.gz, .yaml/.yml ROS map_server, .png/.pgm with or "
    "without a .yaml sidecar; see share/doc/file-formats.md) and, when known, the robot's "
    "trajectory while mapping ('timestamp x y yaw' lines, m and rad in the map frame, as "
    "toposlam-slam writes it). Without a trajectory the medial axis of the free space is "
    "searched instead. A bare picture (no .yaml beside it) is read as a drawn floor plan or "
    "as an occupancy grid, whichever its greys show (a note on stderr says which; --drawn, "
    "--grid).\n"
    "Output, in the folder -o: rooms.json (everything, incl. the label image; schema in "
    "share/doc/file-formats.md), rooms.graphml (the graph), rooms.png (rooms coloured, doors red, "
    "room ids), "
    "rooms-steps.png (what each step found), rooms.topomap.gz (toposlam::rooms::CTopologicalMap "
    "in an MRPT archive). A summary of rooms and doors goes to stdout.\n"
    "Examples:\n"
    "  toposlam-rooms office.gridmap.gz --trajectory office.traj.txt -o office-rooms\n"
    "  toposlam-rooms map.yaml -c config_ini/rooms.ini -o rooms\n"
    "  toposlam-rooms office_a.png -o rooms   # a drawn plan (Bormann PNG), read as one: grey "
    "< 250 is not free, every non-free pixel a wall\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input (a missing or "
    "corrupt map, a map without free cells, a malformed trajectory); 2 for bad options (an "
    "unknown option, a value out of range). Nothing is written unless the segmentation "
    "succeeded.";

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> input(
        "map",
        "Grid map: .gridmap, .gridmap.gz, .yaml/.yml, .png, .pgm (a picture: p(free) = "
        "grey/255 as its .yaml sidecar says, or, without one, see --drawn and --grid)",
        true, "", "map", cmd);
    TCLAP::ValueArg<std::string> output("o", "output", "Output folder (created if needed)", true,
                                        "", "dir", cmd);
    TCLAP::ValueArg<std::string> trajectory(
        "t", "trajectory",
        "Robot trajectory while mapping: 'timestamp x y yaw' per line (s, m, m, rad, map frame). "
        "Default: none, the medial axis of the free space is searched",
        false, "", "file", cmd);
    TCLAP::ValueArg<std::string> config(
        "c", "config",
        "ini file with a [RoomSegmenter] section (all keys optional; see config_ini/rooms.ini for "
        "names, units and defaults). Options given on the command line override it",
        false, "", "file.ini", cmd);
    TCLAP::SwitchArg paper("", "paper",
                           "The paper's method as published: all of TopoSLAM's deviations off, "
                           "every other value (door width, areas, Hough; from -c when given) "
                           "kept",
                           cmd);
    cli::NumberArg<double> doorWidth("", "door-width",
                                     "Door width w in m. Default: 1.1 (with the tolerance: "
                                     "0.6-1.6 m)",
                                     1.1, cli::NumberRange<double>::positive(10), "m", cmd);
    cli::NumberArg<double> doorTolerance("", "door-tolerance",
                                         "Door width tolerance delta_w in m. Default: 0.5", 0.5,
                                         cli::NumberRange<double>::nonNegative(10), "m", cmd);
    cli::NumberArg<double> minRoomArea(
        "", "min-room-area", "Minimum room area N_s in m^2 (both sides of a door). Default: 2", 2.0,
        cli::NumberRange<double>::nonNegative(10000), "m^2", cmd);
    cli::NumberArg<double> freeThreshold(
        "", "free-threshold",
        "A cell is free when p(free) exceeds this. Default: 0.8 (ROS map_server's free "
        "threshold; MRPT grids: unknown = 0.5). 0.98 when read as a drawn plan (--drawn): grey "
        "< 250 is not free, as in Bormann et al.'s benchmark",
        0.8, cli::NumberRange<double>::closed(0.5, 0.999), "p", cmd);
    const cli::MapReadingArgs mapReading(
        cmd,
        "Every non-free pixel is a wall (--free-threshold 0.98 unless given, occupied_threshold "
        "= 1), as toposlam-bench-rooms reads Bormann et al.'s maps.");
    const cli::MapGeometryArgs geometry(cmd);
    cli::NumberArg<int> scale("", "scale", "rooms.png pixels per grid cell. Default: 2", 2,
                              cli::NumberRange<int>::closed(1, 8), "n", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "No summary on stdout", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    std::vector<cli::FileArgument> inputs = cli::mapFilesRead({"", input.getValue()});
    inputs.push_back({"-t", trajectory.getValue()});
    inputs.push_back({"-c", config.getValue()});
    cli::requireOutputsOfTheirOwn(
        inputs, cli::filesInFolder({"-o", output.getValue()}, rooms::roomSegmentationFileNames()));

    rooms::RoomSegmentationJob job;
    job.mapPath = input.getValue();
    job.trajectoryPath = trajectory.getValue();
    job.options = rooms::RoomSegmenter::Options::load(config.getValue(), paper.getValue());
    if (doorWidth.isSet())
        job.options.door.doorWidth = doorWidth.getValue();
    if (doorTolerance.isSet())
        job.options.door.doorWidthTolerance = doorTolerance.getValue();
    if (minRoomArea.isSet())
        job.options.filters.minRoomArea = minRoomArea.getValue();
    if (mapReading.readAsDrawnPlan(input.getValue())) {
        job.options.freeSpace.freeThreshold = io::kDrawnPlanFreeAbove;
        job.options.freeSpace.occupiedThreshold = 1;
    }
    if (freeThreshold.isSet())
        job.options.freeSpace.freeThreshold = freeThreshold.getValue();
    // load() checked the -c file's values on their own (exit 1, naming the file); what fails
    // now, the command line brought in: bad usage, naming its options.
    const auto& door = job.options.door;
    if ((doorWidth.isSet() || doorTolerance.isSet()) &&
        !(door.doorWidthTolerance < door.doorWidth)) {
        std::ostringstream what;
        if (doorWidth.isSet())
            what << "--door-width " << door.doorWidth << (doorTolerance.isSet() ? ", " : "");
        if (doorTolerance.isSet())
            what << "--door-tolerance " << door.doorWidthTolerance;
        what << ": the door width tolerance";
        if (!doorTolerance.isSet())
            what << " (" << door.doorWidthTolerance << " m: --door-tolerance, or -c)";
        what << " must be below the door width";
        if (!doorWidth.isSet())
            what << " (" << door.doorWidth << " m: --door-width, or -c)";
        throw cli::UsageError(what.str());
    }
    try {
        job.options.validate();
    } catch (const config::ConfigError& e) {
        std::string given;
        const std::pair<bool, const char*> options[] = {
            {doorWidth.isSet(), "--door-width"},
            {doorTolerance.isSet(), "--door-tolerance"},
            {minRoomArea.isSet(), "--min-room-area"},
            {freeThreshold.isSet(), "--free-threshold"}};
        for (const auto& [set, name] : options) {
            if (set)
                given += (given.empty() ? "" : ", ") + std::string(name);
        }
        if (given.empty())
            throw;
        throw cli::UsageError(given + ": " + e.what());
    }
    job.geometry = geometry.geometry();

    cli::requireWritableOutputFolder({"-o", output.getValue()});
    const auto result = rooms::runRoomSegmentationJob(job);
    rooms::writeRoomSegmentationFiles(result, output.getValue(), scale.getValue());
    if (!quiet.getValue()) {
        std::cout << rooms::describeRoomSegmentation(result, input.getValue()) << "wrote "
                  << output.getValue()
                  << "/{rooms.json, rooms.graphml, rooms.png, rooms-steps.png, "
                     "rooms.topomap.gz}\n";
    }
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    toposlam::cli::reuseFreedImageMemory();
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
