#include <toposlam/planning/PathShortening.h>
#include <toposlam/planning/RoomToRoomPlanner.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace toposlam::planning {

using mrpt::math::TPoint2D;

namespace {
// How far a requested start or goal may be moved to reach a cell the robot fits in (m): a
// point on a wall or a furniture edge.
constexpr double kSnapDistance = 1.0;
// A door middle may move a fifth of the door's width (a middle on a jamb's rounding, a door
// just wide enough): it stays in the doorway, so a door too narrow for the robot fails.
constexpr double kDoorSnapFraction = 0.2;
}  // namespace

RoomToRoomPlanner::RoomToRoomPlanner(const rooms::TopologicalMap& map,
                                     const TraversabilityGrid& grid,
                                     const OmplPlannerOptions& options)
    : map_(map), grid_(grid), planner_(grid, options) {}

RoomPath RoomToRoomPlanner::plan(int fromRoom, int toRoom) {
    const rooms::Room* a = map_.room(fromRoom);
    const rooms::Room* b = map_.room(toRoom);
    if (!a)
        throw std::invalid_argument("no room with id " + std::to_string(fromRoom));
    if (!b)
        throw std::invalid_argument("no room with id " + std::to_string(toRoom));
    return plan(a->anchor, b->anchor);
}

RoomPath RoomToRoomPlanner::plan(const TPoint2D& startRequest, const TPoint2D& goalRequest) {
    const auto t0 = std::chrono::steady_clock::now();
    RoomPath result;
    const auto finish = [&](const std::string& failure) {
        result.failure = failure;
        result.solved = failure.empty();
        result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return result;
    };
    const auto describe = [](const TPoint2D& p) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "(%.2f, %.2f)", p.x, p.y);
        return std::string(buf);
    };

    // Endpoints: where the robot fits, and in which room.
    TPoint2D ends[2] = {startRequest, goalRequest};
    int endRooms[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const char* what = k == 0 ? "start" : "goal";
        if (!grid_.isTraversable(ends[k].x, ends[k].y)) {
            const auto snapped = grid_.nearestTraversable(ends[k], kSnapDistance);
            if (!snapped) {
                return finish(std::string("the robot does not fit at the ") + what + " " +
                              describe(ends[k]) + " or within 1 m of it");
            }
            ends[k] = *snapped;
        }
        endRooms[k] = map_.roomAt(ends[k].x, ends[k].y);
        if (endRooms[k] == 0) {
            return finish(std::string("the ") + what + " " + describe(ends[k]) +
                          " is in no room of the map");
        }
    }

    const auto route = findRoomRoute(map_, endRooms[0], ends[0], endRooms[1], ends[1]);
    if (!route) {
        return finish("rooms " + std::to_string(endRooms[0]) + " and " +
                      std::to_string(endRooms[1]) + " are not connected by doors");
    }
    result.route = *route;

    // Door middles the robot cannot stand on (a door barely wider than the robot, a middle
    // on a jamb's rounding) move to the nearest cell it fits in.
    std::vector<TPoint2D>& waypoints = result.route.waypoints;
    for (std::size_t i = 1; i + 1 < waypoints.size(); ++i) {
        if (grid_.isTraversable(waypoints[i].x, waypoints[i].y))
            continue;
        const rooms::Door& door =
            map_.doors[static_cast<std::size_t>(result.route.doors[i - 1] - 1)];
        const auto snapped = grid_.nearestTraversable(waypoints[i], kDoorSnapFraction * door.width);
        if (!snapped) {
            return finish("door " + std::to_string(result.route.doors[i - 1]) +
                          " is too narrow for the robot");
        }
        waypoints[i] = *snapped;
    }

    // Each leg stays inside one room: straight when that is free, else planned.
    std::vector<TPoint2D> path{waypoints.front()};
    for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
        if (grid_.isSegmentTraversable(waypoints[i], waypoints[i + 1])) {
            path.push_back(waypoints[i + 1]);
            continue;
        }
        const auto leg = planner_.plan(waypoints[i], waypoints[i + 1]);
        if (!leg) {
            return finish("no path found from " + describe(waypoints[i]) + " to " +
                          describe(waypoints[i + 1]) + " within the time limit");
        }
        path.insert(path.end(), leg->begin() + 1, leg->end());
    }
    result.points = shortenPath(grid_, path);
    result.length = polylineLength(result.points);
    return finish("");
}

}  // namespace toposlam::planning
