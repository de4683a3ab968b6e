// toposlam-plan: a room-to-room path on a topological map (toposlam-rooms output) and its
// occupancy grid. The planning lives in libs/planning.
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/MapReadingArgs.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/planning/RoomPlanRequest.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace toposlam;

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
    "Exit status: 0 when a path was found; 1 with 'error: ...' on bad input (unreadable files, "
    "rooms from another map); 2 on bad usage (an option out of range, a room that does not "
    "exist); 3 when no path exists (the reason is printed; nothing is written).";

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
    cli::NumberArg<double> radiusArg(
        "", "robot-radius", "robot radius in m: the clearance kept from obstacles. Default 0.25",
        0.25, cli::NumberRange<double>::positive(10), "m", cmd);
    std::vector<std::string> planners = planning::omplPlannerNames();
    TCLAP::ValuesConstraint<std::string> plannerNames(planners);
    TCLAP::ValueArg<std::string> plannerArg(
        "", "planner",
        "OMPL planner: rrtconnect (default), rrtstar, informedrrtstar, prmstar, bitstar", false,
        "rrtconnect", &plannerNames, cmd);
    cli::NumberArg<double> timeArg(
        "", "time",
        "planning time limit per leg in s (asymptotically optimal planners use all of it). "
        "Default 1",
        1.0, cli::NumberRange<double>::positive(3600), "s", cmd);
    cli::NumberArg<double> freeThresholdArg(
        "", "free-threshold",
        "cells with p(free) above this are free; everything else (occupied, unknown) is an "
        "obstacle. Default 0.6, or 0.98 for a map read as a drawn plan (--drawn)",
        0.6, cli::NumberRange<double>::closed(0.5, 0.999), "p", cmd);
    const cli::MapReadingArgs mapReading(
        cmd, "Use the picture the rooms were segmented from, read the same way.");
    cli::NumberArg<int> attemptsArg(
        "", "attempts",
        "independent OMPL solves per leg, the shortest kept (RRT-Connect picks a random side "
        "of each obstacle). Default 3",
        3, cli::NumberRange<int>::positive(1000), "n", cmd);
    cli::NumberArg<unsigned> seedArg("", "seed",
                                     "seed of OMPL's random sampling, for reproducible paths. "
                                     "Default 1",
                                     1, cli::NumberRange<unsigned>::positive(2147483647), "n", cmd);
    if (const auto exitCode = cli::parseCommandLine(cmd, argc, argv))
        return *exitCode;

    std::vector<cli::FileArgument> inputs = cli::mapFilesRead({"", mapArg.getValue()});
    inputs.push_back({"", roomsArg.getValue()});
    cli::requireOutputsOfTheirOwn(
        inputs, cli::filesInFolder({"-o", outArg.getValue()}, planning::roomPlanFileNames()));
    cli::requireWritableOutputFolder({"-o", outArg.getValue()});  // before planning, not after

    planning::RoomPlanRequest request;
    request.gridFile = mapArg.getValue();
    request.roomsFile = roomsArg.getValue();
    request.from = fromArg.getValue();
    request.to = toArg.getValue();
    request.robotRadius = radiusArg.getValue();
    request.freeThreshold = freeThresholdArg.getValue();
    if (mapReading.readAsDrawnPlan(request.gridFile) && !freeThresholdArg.isSet())
        request.freeThreshold = io::kDrawnPlanFreeAbove;
    request.ompl.planner = plannerArg.getValue();
    request.ompl.timeLimit = timeArg.getValue();
    request.ompl.attempts = attemptsArg.getValue();
    request.seed = seedArg.getValue();
    planning::RoomPlan plan;
    try {
        plan = planning::planRoomToRoom(request);
    } catch (const planning::EndpointError& e) {
        throw cli::UsageError(e.what());
    }
    if (!plan.path.solved) {
        std::cerr << planning::describeRoomPlan(plan);
        return cli::kNoResult;
    }
    std::cout << planning::describeRoomPlan(plan);
    for (const std::string& file : planning::saveRoomPlan(plan, outArg.getValue()))
        std::cout << "wrote " << file << "\n";
    return cli::kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    return toposlam::cli::runReportingErrors(run, argc, argv);
}
