#pragma once
// Shortest paths for a disc-shaped robot (or person) on an occupancy grid: A* for one query,
// Dijkstra for the costs from one cell to all. Moves are 8-connected between cells whose
// clearance (ClearanceMap) is at least the robot's required clearance; diagonal moves may not cut
// corners. A step costs its length times a penalty that grows as clearance drops below a
// preferred value, so paths keep to the middle of corridors and doorways, as people and robot
// navigation stacks do.
#include <toposlam/simulation/ClearanceMap.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace toposlam::simulation {

struct PathCostOptions {
    /// m; cells with less clearance are not traversable (robot radius + safety margin).
    double minClearance = 0.30;
    /// m; clearance above which a step costs just its length.
    double preferredClearance = 0.8;
    /// Cost factor of a step in a cell at minimal clearance is 1 + clearanceWeight.
    double clearanceWeight = 3.0;
};

class GridPathPlanner {
  public:
    static constexpr float kUnreachable = std::numeric_limits<float>::infinity();

    GridPathPlanner(const ClearanceMap& map, const PathCostOptions& options);

    const ClearanceMap& map() const { return map_; }
    const PathCostOptions& options() const { return options_; }
    bool traversable(int cx, int cy) const {
        return map_.geometry().contains(cx, cy) &&
               stepFactor_[map_.geometry().index(cx, cy)] > 0.0f;
    }
    bool traversable(const mrpt::math::TPoint2D& p) const {
        return traversable(map_.geometry().cellX(p.x), map_.geometry().cellY(p.y));
    }

    /// Cheapest path from the cell of `from` to the cell of `to`: the cell centres (world frame,
    /// m) in order, the first and last replaced by `from` and `to` themselves. Empty when either
    /// end is not traversable or no path exists.
    std::vector<mrpt::math::TPoint2D> plan(const mrpt::math::TPoint2D& from,
                                           const mrpt::math::TPoint2D& to);

    /// Path cost (m, clearance-weighted) from the cell of `from` to every cell (indexed by
    /// GridGeometry::index; kUnreachable where there is no path). The reference stays valid
    /// until the next call.
    const std::vector<float>& costsFrom(const mrpt::math::TPoint2D& from);

  private:
    struct QueueEntry {
        float priority;
        std::uint32_t cell;
        bool operator<(const QueueEntry& o) const { return priority > o.priority; }  // min-heap
    };
    /// Shared A*/Dijkstra search; goal < 0: no goal (Dijkstra over the whole component).
    bool search(std::uint32_t start, long goal);

    const ClearanceMap& map_;
    PathCostOptions options_;
    std::vector<float> stepFactor_;  ///< per cell: cost per metre entering it; 0 = blocked
    // Workspaces reused by every query.
    std::vector<float> cost_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint8_t> closed_;
    std::vector<QueueEntry> heap_;
    double goalX_ = 0, goalY_ = 0;
};

}  // namespace toposlam::simulation
