// toposlam-rooms: room segmentation of an occupancy grid by virtual-door detection, written as
// a topological map (rooms = nodes, doors = edges) in JSON, GraphML, PNG and MRPT formats.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/rooms/CTopologicalMap.h>
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/TopologicalMapIO.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
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
    "searched instead.\n"
    "Output, in the folder -o: rooms.json (everything, incl. the label image; schema in "
    "share/doc/file-formats.md), rooms.graphml (the graph), rooms.png (rooms coloured, doors red, "
    "room ids), "
    "rooms-steps.png (what each step found), rooms.topomap.gz (toposlam::rooms::CTopologicalMap "
    "in an MRPT archive). A summary of rooms and doors goes to stdout.\n"
    "Examples:\n"
    "  toposlam-rooms office.gridmap.gz --trajectory office.traj.txt -o office-rooms\n"
    "  toposlam-rooms map.yaml -c config_ini/rooms.ini -o rooms\n"
    "  toposlam-rooms office_a.png --free-threshold 0.98 -o rooms   # Bormann PNG: grey < 250 is "
    "not free\n"
    "Exit status: 0 on success; 1 with 'error: ...' on stderr for bad input (a missing or "
    "corrupt map, a map without free cells, a malformed trajectory); 2 for bad options (an "
    "unknown option, a value out of range). Nothing is written unless the segmentation "
    "succeeded.";

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> input(
        "map",
        "Grid map: .gridmap, .gridmap.gz, .yaml/.yml, .png, .pgm (image: p(free) = "
        "grey/255 unless its .yaml sidecar says otherwise)",
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
                           "The paper's method as published: TopoSLAM's deviations off (same as "
                           "'variant = paper' in the ini file)",
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
        "threshold; MRPT grids: unknown = 0.5). Use 0.98 for maps drawn with grey < 250 = not "
        "free (Bormann et al.'s benchmark)",
        0.8, cli::NumberRange<double>::closed(0.5, 0.999), "p", cmd);
    cli::NumberArg<double> resolution(
        "", "resolution",
        "Cell size in m of a bare input image (overrides its .yaml sidecar). "
        "Default: the sidecar's, else 0.05",
        0.05, cli::NumberRange<double>::positive(100), "m", cmd);
    TCLAP::ValueArg<std::string> origin(
        "", "origin",
        "World x,y (m) of the lower-left corner of a bare input image. Default: "
        "the sidecar's, else 0,0",
        false, "", "x,y", cmd);
    cli::NumberArg<int> scale("", "scale", "rooms.png pixels per grid cell. Default: 2", 2,
                              cli::NumberRange<int>::closed(1, 8), "n", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "No summary on stdout", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    rooms::RoomSegmenter::Options options;
    if (paper.getValue())
        options = rooms::RoomSegmenter::Options::paperExact();
    if (!config.getValue().empty()) {
        if (!std::filesystem::is_regular_file(config.getValue())) {
            throw io::InputError(config.getValue(), "no such config file");
        }
        options.loadFromConfigFile(mrpt::config::CConfigFile(config.getValue()), "RoomSegmenter");
        if (paper.getValue()) {  // --paper wins over the file's variant, keeps its values
            const auto exact = rooms::RoomSegmenter::Options::paperExact();
            options.door.localDirection = exact.door.localDirection;
            options.filters.keepNarrowestOfGroup = exact.filters.keepNarrowestOfGroup;
            options.filters.mergeSmallestFirst = exact.filters.mergeSmallestFirst;
            options.filters.requireWallJambs = exact.filters.requireWallJambs;
            options.filters.requireConstriction = exact.filters.requireConstriction;
        }
    }
    if (doorWidth.isSet())
        options.door.doorWidth = doorWidth.getValue();
    if (doorTolerance.isSet())
        options.door.doorWidthTolerance = doorTolerance.getValue();
    if (minRoomArea.isSet())
        options.filters.minRoomArea = minRoomArea.getValue();
    if (freeThreshold.isSet())
        options.freeSpace.freeThreshold = freeThreshold.getValue();
    options.validate();

    std::optional<io::GridMapGeometry> geometry;
    if (resolution.isSet() || origin.isSet()) {
        geometry.emplace();
        if (resolution.isSet())
            geometry->resolution = resolution.getValue();
        if (origin.isSet()) {
            const auto xy = cli::parseNumberList(origin.getValue(), 2, "--origin");
            geometry->originX = xy[0];
            geometry->originY = xy[1];
        }
    }
    const auto grid = io::loadGridMap(input.getValue(), geometry);
    std::vector<mrpt::math::TPose2D> poses;
    if (!trajectory.getValue().empty()) {
        for (const auto& p : io::loadTrajectory(trajectory.getValue()))
            poses.push_back(p.pose);
        if (poses.empty())
            throw io::InputError(trajectory.getValue(), "the trajectory has no poses");
    }

    const rooms::RoomSegmenter segmenter(options);
    const auto result = segmenter.segment(grid, poses, input.getValue());
    if (result.fromTrajectory && result.searchCells.empty()) {
        throw io::InputError(trajectory.getValue(),
                             "no pose of the trajectory lies in the map's free space (wrong "
                             "frame or wrong file?)");
    }

    const std::filesystem::path dir(output.getValue());
    std::filesystem::create_directories(dir);
    rooms::saveTopologicalMapJson(result.map, (dir / "rooms.json").string());
    rooms::saveTopologicalMapGraphML(result.map, (dir / "rooms.graphml").string());
    rooms::RenderOptions render;
    render.scale = scale.getValue();
    render.doorIds = true;
    rooms::saveTopologicalMapPng(result.map, (dir / "rooms.png").string(), render);
    // What each step saw, over the binarised map.
    cv::Mat free(result.map.labels.size(), CV_8U, cv::Scalar(0));
    free.setTo(255, result.map.labels > 0);
    const cv::Mat steps = rooms::renderDiagnostics(result, free);
    io::writeFileAtomically((dir / "rooms-steps.png").string(), [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, steps))
            throw std::runtime_error(tmp + ": cannot write the PNG");
    });
    io::writeFileAtomically((dir / "rooms.topomap.gz").string(), [&](const std::string& tmp) {
        mrpt::io::CFileGZOutputStream out(tmp);
        mrpt::serialization::archiveFrom(out) << rooms::CTopologicalMap(result.map);
    });

    if (!quiet.getValue()) {
        const auto& m = result.map;
        std::printf("%s: %zu rooms, %zu doors (%s search, %zu candidate doors, %.1f ms)\n",
                    input.getValue().c_str(), m.rooms.size(), m.doors.size(),
                    result.fromTrajectory ? "trajectory" : "medial-axis", result.candidates.size(),
                    result.milliseconds);
        for (const auto& r : m.rooms) {
            std::printf("  room %3d  %8.2f m^2  centroid (%.2f, %.2f)  neighbours:", r.id, r.area,
                        r.centroid.x, r.centroid.y);
            for (int n : m.neighbours(r.id))
                std::printf(" %d", n);
            std::printf("\n");
        }
        for (const auto& d : m.doors) {
            std::printf("  door %3d  rooms %d-%d  %.2f m wide at (%.2f, %.2f)\n", d.id, d.roomA,
                        d.roomB, d.width, d.middle().x, d.middle().y);
        }
        std::printf(
            "wrote %s/{rooms.json, rooms.graphml, rooms.png, rooms-steps.png, "
            "rooms.topomap.gz}\n",
            dir.string().c_str());
    }
    return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
