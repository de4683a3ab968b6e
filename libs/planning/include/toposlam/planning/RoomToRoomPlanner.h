#pragma once
// Room-to-room paths on a topological map: the room route (RoomRoute) says which doors to go
// through; OMPL connects consecutive waypoints (start, door middles, goal), each leg inside one
// room, so the sampling planner never has to find a narrow doorway by chance (legs in line of
// sight are straight and need no planning); the joined path is then pulled taut as a whole
// (PathShortening).
#include <toposlam/planning/OmplPathPlanner.h>
#include <toposlam/planning/RoomPath.h>
#include <toposlam/planning/TraversabilityGrid.h>
#include <toposlam/rooms/TopologicalMap.h>

namespace toposlam::planning {

class RoomToRoomPlanner {
  public:
    /// `map` and `grid` must come from the same occupancy grid.
    RoomToRoomPlanner(const rooms::TopologicalMap& map, const TraversabilityGrid& grid,
                      const OmplPlannerOptions& options = {});

    /// From the anchor of room `fromRoom` to the anchor of room `toRoom` (ids; the anchor is the
    /// room's most open point). Throws std::invalid_argument for an unknown id.
    RoomPath plan(int fromRoom, int toRoom);
    /// Between two world points (m); each must lie in a room or within 1 m of a traversable
    /// cell of one.
    RoomPath plan(const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& goal);

  private:
    const rooms::TopologicalMap& map_;
    const TraversabilityGrid& grid_;
    OmplPathPlanner planner_;
};

}  // namespace toposlam::planning
