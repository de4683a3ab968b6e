#include <toposlam/planning/RoomRoute.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace toposlam::planning {

using mrpt::math::TPoint2D;

std::optional<RoomRoute> findRoomRoute(const rooms::TopologicalMap& map, int startRoom,
                                       const TPoint2D& start, int goalRoom, const TPoint2D& goal) {
    for (const int id : {startRoom, goalRoom}) {
        if (!map.room(id))
            throw std::invalid_argument("no room with id " + std::to_string(id));
    }
    // Nodes: 0 = start, 1 = goal, 2 + i = door i. Each node lies in one or two rooms; two nodes
    // are linked when they share a room.
    const std::size_t n = 2 + map.doors.size();
    const auto position = [&](std::size_t k) {
        return k == 0 ? start : (k == 1 ? goal : map.doors[k - 2].middle());
    };
    const auto inRoom = [&](std::size_t k, int room) {
        if (k == 0)
            return room == startRoom;
        if (k == 1)
            return room == goalRoom;
        const auto& d = map.doors[k - 2];
        return d.roomA == room || d.roomB == room;
    };
    const auto sharedRoom = [&](std::size_t a, std::size_t b) {
        for (const int r : {startRoom, goalRoom}) {
            if (inRoom(a, r) && inRoom(b, r))
                return true;
        }
        if (a >= 2) {
            const auto& d = map.doors[a - 2];
            return inRoom(b, d.roomA) || inRoom(b, d.roomB);
        }
        return false;
    };

    // Dijkstra, O(n^2): floors have tens of doors.
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<int> parent(n, -1);
    std::vector<bool> done(n, false);
    dist[0] = 0;
    for (;;) {
        std::size_t u = n;
        for (std::size_t k = 0; k < n; ++k) {
            if (!done[k] && std::isfinite(dist[k]) && (u == n || dist[k] < dist[u]))
                u = k;
        }
        if (u == n || u == 1)
            break;
        done[u] = true;
        const TPoint2D pu = position(u);
        for (std::size_t v = 0; v < n; ++v) {
            if (done[v] || !sharedRoom(u, v))
                continue;
            const TPoint2D pv = position(v);
            const double d = dist[u] + std::hypot(pv.x - pu.x, pv.y - pu.y);
            if (d < dist[v]) {
                dist[v] = d;
                parent[v] = static_cast<int>(u);
            }
        }
    }
    if (!std::isfinite(dist[1]))
        return std::nullopt;

    std::vector<std::size_t> nodes;
    for (int k = 1; k != -1; k = parent[static_cast<std::size_t>(k)])
        nodes.push_back(static_cast<std::size_t>(k));
    RoomRoute route;
    route.estimatedLength = dist[1];
    route.rooms.push_back(startRoom);
    for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
        route.waypoints.push_back(position(*it));
        if (*it < 2)
            continue;
        const auto& d = map.doors[*it - 2];
        route.doors.push_back(d.id);
        route.rooms.push_back(d.roomA == route.rooms.back() ? d.roomB : d.roomA);
    }
    return route;
}

}  // namespace toposlam::planning
