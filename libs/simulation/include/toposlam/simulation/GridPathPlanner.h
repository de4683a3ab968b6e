#pragma once
// Shortest paths for a disc-shaped robot (or person) on an occupancy grid: A* for one query,
// Dijkstra for the costs from one cell to all (both by gridpath::GridAStar). Moves are
// 8-connected between cells whose clearance (ClearanceMap) is at least the robot's required
// clearance; diagonal moves may not cut corners. A step costs its length times a penalty that
// grows as clearance drops below a preferred value, so paths keep to the middle of corridors
// and doorways, as people and robot navigation stacks do.
#include <toposlam/gridpath/GridAStar.h>
#include <toposlam/simulation/ClearanceMap.h>

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
    static constexpr float kUnreachable = gridpath::GridAStar::kUnreachable;

    GridPathPlanner(const ClearanceMap& map, const PathCostOptions& options);

    const ClearanceMap& map() const { return map_; }
    const PathCostOptions& options() const { return options_; }
    bool traversable(int cx, int cy) const { return search_.traversable(cx, cy); }
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

    /// Path cost (m, clearance-weighted) from the cell of `from` to the cell of each of `to`,
    /// in their order (kUnreachable where there is no path): costsFrom()'s values for those
    /// cells, from a search that stops once it has reached them all.
    std::vector<float> costsTo(const mrpt::math::TPoint2D& from,
                               const std::vector<mrpt::math::TPoint2D>& to);

  private:
    /// The grid index of the cell holding `p`; outside the grid an index past the end, which
    /// GridAStar reports as unreachable.
    std::size_t cellOf(const mrpt::math::TPoint2D& p) const;

    const ClearanceMap& map_;
    PathCostOptions options_;
    gridpath::GridAStar search_;  ///< step costs: the clearance penalty per cell, 0 = blocked
};

}  // namespace toposlam::simulation
