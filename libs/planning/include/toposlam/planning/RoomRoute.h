#pragma once
// The topological half of room-to-room planning: which rooms, and which doors between them,
// a path takes. Dijkstra over a graph whose nodes are the start, the goal and the middles of
// the doors, linking every two of them that share a room by their straight-line distance (a
// lower bound of the walk inside the room). The metric planner then only has to connect
// consecutive waypoints, each leg inside one room.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <optional>
#include <vector>

namespace toposlam::planning {

struct RoomRoute {
    std::vector<int> rooms;  ///< room ids from the start room to the goal room
    std::vector<int> doors;  ///< door ids crossed, doors[i] joins rooms[i] and rooms[i+1]
    /// start, the middle of each door, goal (m, world frame)
    std::vector<mrpt::math::TPoint2D> waypoints;
    double estimatedLength = 0;  ///< m, along the waypoints
};

/// Route from `start` in room `startRoom` to `goal` in room `goalRoom` (ids of `map`).
/// nullopt when the rooms are not connected by doors. Throws std::invalid_argument for an
/// unknown room id.
std::optional<RoomRoute> findRoomRoute(const rooms::TopologicalMap& map, int startRoom,
                                       const mrpt::math::TPoint2D& start, int goalRoom,
                                       const mrpt::math::TPoint2D& goal);

}  // namespace toposlam::planning
