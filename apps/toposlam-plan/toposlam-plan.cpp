// toposlam-plan: a room-to-room path on a topological map (toposlam-rooms output) and its
// occupancy grid. The planning lives in libs/planning.
#include <ompl/util/RandomNumbers.h>
#include <toposlam/cli/CommandLine.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/planning/PathRendering.h>
#include <toposlam/planning/RoomToRoomPlanner.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace {

using namespace toposlam;
namespace fs = std::filesystem;

const char* const kDescription =
    "Plans a collision-free path for a disc-shaped robot from one room to another. The room "
    "graph (rooms = nodes, doors = edges) gives the sequence of doors (Dijkstra); OMPL "
    "connects the waypoints inside each room; the joined path is shortened as a whole.\n"
    "Inputs: the occupancy grid the rooms were segmented from (.gridmap(.gz), .yaml, .png "
    "with sidecar) and the topological map written by toposlam-rooms (rooms.json or "
    "rooms.graphml). Rooms are given by id, by name, or as a world point 'x,y' (m).\n"
    "Output, in the folder -o: path.txt (route as comments, then 'x y' per line, m, map "
    "frame) and path.png (rooms coloured, route doors yellow, path red, start green, goal "
    "blue). The route and the length go to stdout.\n"
    "Example:\n"
    "  toposlam-plan slam-out/map.gridmap.gz rooms-out/rooms.json --from 2 --to 11 -o plan\n"
    "Exit status: 0 when a path was found; 1 with 'error: ...' on bad input; 3 when no path "
    "exists (the reason is printed; nothing is written).";

struct Endpoint {
    std::optional<int> room;
    mrpt::math::TPoint2D point;
};

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// "3" -> room 3, "kitchen" -> the room named so, "4.5,2" -> a world point.
Endpoint parseEndpoint(const std::string& text, const rooms::TopologicalMap& map,
                       const std::string& option) {
    if (text.find(',') != std::string::npos) {
        const auto xy = cli::parseNumberList(text, 2, option);
        return {std::nullopt, {xy[0], xy[1]}};
    }
    char* end = nullptr;
    const long id = std::strtol(text.c_str(), &end, 10);
    if (!text.empty() && *end == '\0') {
        if (!map.room(static_cast<int>(id))) {
            throw std::invalid_argument(option + ": no room with id " + text + " (the map has " +
                                        std::to_string(map.rooms.size()) + " rooms)");
        }
        return {static_cast<int>(id), map.room(static_cast<int>(id))->anchor};
    }
    for (const auto& r : map.rooms) {
        if (!r.name.empty() && lowercase(r.name) == lowercase(text))
            return {r.id, r.anchor};
    }
    throw std::invalid_argument(option + ": no room named '" + text + "'");
}

// The room whose anchor is farthest (straight line) from `p`.
Endpoint farthestRoom(const rooms::TopologicalMap& map, const mrpt::math::TPoint2D& p) {
    if (map.rooms.empty())
        throw std::invalid_argument("the topological map has no rooms");
    const rooms::Room* best = &map.rooms.front();
    for (const auto& r : map.rooms) {
        if (std::hypot(r.anchor.x - p.x, r.anchor.y - p.y) >
            std::hypot(best->anchor.x - p.x, best->anchor.y - p.y)) {
            best = &r;
        }
    }
    return {best->id, best->anchor};
}

std::string roomLabel(const rooms::TopologicalMap& map, int id) {
    const rooms::Room* r = map.room(id);
    return "room " + std::to_string(id) + (r && !r->name.empty() ? " (" + r->name + ")" : "");
}

int run(int argc, char** argv) {
    TCLAP::CmdLine cmd(kDescription, ' ', "0.1.0");
    TCLAP::UnlabeledValueArg<std::string> mapArg("map", "occupancy grid", true, "", "map", cmd);
    TCLAP::UnlabeledValueArg<std::string> roomsArg(
        "rooms", "topological map: rooms.json or rooms.graphml from toposlam-rooms", true, "",
        "rooms", cmd);
    TCLAP::ValueArg<std::string> fromArg("", "from", "start: room id, room name or x,y (m)", true,
                                         "", "room", cmd);
    TCLAP::ValueArg<std::string> toArg(
        "", "to",
        "goal: room id, room name, x,y (m), or 'farthest' (the room farthest from the start)", true,
        "", "room", cmd);
    TCLAP::ValueArg<std::string> outArg("o", "out", "output folder (created). Default: plan-out",
                                        false, "plan-out", "dir", cmd);
    TCLAP::ValueArg<double> radiusArg(
        "", "robot-radius", "robot radius in m: the clearance kept from obstacles. Default 0.25",
        false, 0.25, "m", cmd);
    TCLAP::ValueArg<std::string> plannerArg(
        "", "planner",
        "OMPL planner: rrtconnect (default), rrtstar, informedrrtstar, prmstar, bitstar", false,
        "rrtconnect", "name", cmd);
    TCLAP::ValueArg<double> timeArg(
        "", "time",
        "planning time limit per leg in s (asymptotically optimal planners use all of it). "
        "Default 1",
        false, 1.0, "s", cmd);
    TCLAP::ValueArg<double> freeThresholdArg(
        "", "free-threshold",
        "cells with p(free) above this are free; everything else (occupied, unknown) is an "
        "obstacle. Default 0.6 (use 0.98 for Bormann-style PNGs, where grey < 250 is not free)",
        false, 0.6, "p", cmd);
    TCLAP::ValueArg<int> attemptsArg(
        "", "attempts",
        "independent OMPL solves per leg, the shortest kept (RRT-Connect picks a random side "
        "of each obstacle). Default 3",
        false, 3, "n", cmd);
    TCLAP::ValueArg<unsigned> seedArg(
        "", "seed", "seed of OMPL's random sampling, for reproducible paths. Default 1", false, 1,
        "n", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    ompl::RNG::setSeed(seedArg.getValue());  // before any OMPL sampler exists
    planning::OmplPlannerOptions options;
    options.planner = plannerArg.getValue();
    options.timeLimit = timeArg.getValue();
    options.attempts = attemptsArg.getValue();
    options.validate();
    if (!(radiusArg.getValue() > 0))
        throw std::invalid_argument("--robot-radius must be > 0");

    const auto grid = io::loadGridMap(mapArg.getValue());
    const rooms::TopologicalMap map = rooms::loadTopologicalMap(roomsArg.getValue());
    if (map.frame.cols != static_cast<int>(grid.getSizeX()) ||
        map.frame.rows != static_cast<int>(grid.getSizeY())) {
        throw io::InputError(roomsArg.getValue(),
                             "the rooms were segmented from another map (size differs from " +
                                 mapArg.getValue() + ")");
    }
    const Endpoint from = parseEndpoint(fromArg.getValue(), map, "--from");
    const Endpoint to = toArg.getValue() == "farthest"
                            ? farthestRoom(map, from.point)
                            : parseEndpoint(toArg.getValue(), map, "--to");

    const planning::TraversabilityGrid traversable(grid, radiusArg.getValue(),
                                                   freeThresholdArg.getValue());
    planning::RoomToRoomPlanner planner(map, traversable, options);
    const planning::RoomPath path = planner.plan(from.point, to.point);
    if (!path.solved) {
        std::cerr << "no path: " << path.failure << "\n";
        return 3;
    }

    std::printf("route:");
    for (std::size_t i = 0; i < path.route.rooms.size(); ++i) {
        if (i > 0)
            std::printf(" -> door %d ->", path.route.doors[i - 1]);
        std::printf(" %s", roomLabel(map, path.route.rooms[i]).c_str());
    }
    std::printf("\nlength: %.2f m, %zu points, planned in %.1f ms (%s)\n", path.length,
                path.points.size(), 1e3 * path.seconds, options.planner.c_str());
    const fs::path out(outArg.getValue());
    fs::create_directories(out);
    planning::savePath(path, (out / "path.txt").string());
    planning::saveRoomPathPng(map, path, (out / "path.png").string());
    std::printf("wrote %s\nwrote %s\n", (out / "path.txt").c_str(), (out / "path.png").c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
