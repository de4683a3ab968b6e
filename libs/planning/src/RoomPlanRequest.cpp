#include <ompl/util/RandomNumbers.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>
#include <toposlam/planning/PathRendering.h>
#include <toposlam/planning/RoomPlanRequest.h>
#include <toposlam/planning/RoomToRoomPlanner.h>
#include <toposlam/planning/TraversabilityGrid.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace toposlam::planning {

namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::optional<double> finiteNumber(const std::string& text) {
    double v = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::string roomLabel(const rooms::TopologicalMap& map, int id) {
    const rooms::Room* r = map.room(id);
    return "room " + std::to_string(id) + (r && !r->name.empty() ? " (" + r->name + ")" : "");
}

}  // namespace

Endpoint resolveEndpoint(const std::string& text, const rooms::TopologicalMap& map,
                         const std::string& option) {
    if (const auto comma = text.find(','); comma != std::string::npos) {
        const auto x = finiteNumber(text.substr(0, comma));
        const auto y = finiteNumber(text.substr(comma + 1));
        if (!x || !y)
            throw EndpointError(option + ": '" + text + "' is not a point x,y (m)");
        return {std::nullopt, {*x, *y}};
    }
    int id = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
    if (!text.empty() && error == std::errc() && end == text.data() + text.size()) {
        const rooms::Room* room = map.room(id);
        if (!room) {
            throw EndpointError(option + ": no room with id " + text + " (the map has " +
                                std::to_string(map.rooms.size()) + " rooms)");
        }
        return {id, room->anchor};
    }
    for (const auto& r : map.rooms) {
        if (!r.name.empty() && lowercase(r.name) == lowercase(text))
            return {r.id, r.anchor};
    }
    throw EndpointError(option + ": no room named '" + text + "'");
}

Endpoint farthestRoom(const rooms::TopologicalMap& map, const mrpt::math::TPoint2D& p) {
    if (map.rooms.empty())
        throw EndpointError("--to farthest: the topological map has no rooms");
    const auto distance = [&](const rooms::Room& r) {
        return std::hypot(r.anchor.x - p.x, r.anchor.y - p.y);
    };
    const auto best = std::max_element(
        map.rooms.begin(), map.rooms.end(),
        [&](const rooms::Room& a, const rooms::Room& b) { return distance(a) < distance(b); });
    return {best->id, best->anchor};
}

void checkRoomsFitGrid(const rooms::TopologicalMap& map,
                       const mrpt::maps::COccupancyGridMap2D& grid, const std::string& roomsFile,
                       const std::string& gridFile) {
    if (map.labels.empty()) {
        throw io::InputError(roomsFile,
                             "the topological map has no room cells (label image), so points "
                             "cannot be placed in rooms; write it with toposlam-rooms");
    }
    const auto cols = static_cast<int>(grid.getSizeX()), rows = static_cast<int>(grid.getSizeY());
    if (map.frame.cols != cols || map.frame.rows != rows) {
        throw io::InputError(roomsFile, "the rooms were segmented from another map (" +
                                            std::to_string(map.frame.cols) + " x " +
                                            std::to_string(map.frame.rows) + " cells, " + gridFile +
                                            " has " + std::to_string(cols) + " x " +
                                            std::to_string(rows) + ")");
    }
    const double tolerance = 0.01 * grid.getResolution();
    if (std::abs(map.frame.resolution - grid.getResolution()) > tolerance ||
        std::abs(map.frame.xMin - grid.getXMin()) > tolerance ||
        std::abs(map.frame.yMin - grid.getYMin()) > tolerance) {
        throw io::InputError(roomsFile,
                             "the rooms were segmented from another map (resolution "
                             "or origin differs from " +
                                 gridFile + ")");
    }
}

RoomPlan planRoomToRoom(const RoomPlanRequest& request) {
    request.ompl.validate();
    if (!(request.robotRadius > 0) || !std::isfinite(request.robotRadius))
        throw std::invalid_argument("the robot radius must be > 0");
    if (request.seed)
        ompl::RNG::setSeed(*request.seed);  // before any OMPL sampler exists
    const auto grid = io::loadGridMap(request.gridFile);
    RoomPlan plan;
    plan.planner = request.ompl.planner;
    plan.map = rooms::loadTopologicalMap(request.roomsFile);
    checkRoomsFitGrid(plan.map, grid, request.roomsFile, request.gridFile);
    const Endpoint from = resolveEndpoint(request.from, plan.map, "--from");
    const Endpoint to = request.to == "farthest" ? farthestRoom(plan.map, from.point)
                                                 : resolveEndpoint(request.to, plan.map, "--to");
    const TraversabilityGrid traversable(grid, request.robotRadius, request.freeThreshold);
    RoomToRoomPlanner planner(plan.map, traversable, request.ompl);
    plan.path = planner.plan(from.point, to.point);
    return plan;
}

std::string describeRoomPlan(const RoomPlan& plan) {
    const RoomPath& path = plan.path;
    if (!path.solved)
        return "no path: " + path.failure + "\n";
    std::string out = "route:";
    for (std::size_t i = 0; i < path.route.rooms.size(); ++i) {
        if (i > 0)
            out += " -> door " + std::to_string(path.route.doors[i - 1]) + " ->";
        out += " " + roomLabel(plan.map, path.route.rooms[i]);
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "\nlength: %.2f m, %zu points, planned in %.1f ms (%s)\n",
                  path.length, path.points.size(), 1e3 * path.seconds, plan.planner.c_str());
    return out + buf;
}

std::vector<std::string> roomPlanFileNames() {
    return {"path.txt", "path.png"};
}

std::vector<std::string> saveRoomPlan(const RoomPlan& plan, const std::string& folder) {
    const std::filesystem::path out(folder);
    std::filesystem::create_directories(out);
    const std::vector<std::string> names = roomPlanFileNames();
    const std::string text = (out / names[0]).string(), png = (out / names[1]).string();
    io::OutputGroup files;  // both or neither
    savePath(plan.path, text);
    saveRoomPathPng(plan.map, plan.path, png);
    files.commit();
    return {text, png};
}

}  // namespace toposlam::planning
