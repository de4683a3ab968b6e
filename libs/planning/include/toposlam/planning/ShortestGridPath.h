#pragma once
// The reference shortest path: the shortest 8-connected path over the traversable cells of a
// TraversabilityGrid (gridpath::GridAStar, every step cost 1; diagonal steps may not cut a
// blocked corner). It is what sampling-based plans are compared with: optimal on the grid, but
// its length includes the grid's staircase (up to ~8 % longer than the true shortest path).
#include <mrpt/math/TPoint2D.h>
#include <toposlam/gridpath/GridAStar.h>
#include <toposlam/planning/TraversabilityGrid.h>

#include <optional>
#include <vector>

namespace toposlam::planning {

struct GridPath {
    std::vector<mrpt::math::TPoint2D> points;  ///< cell centres, world frame (m)
    double length = 0;                         ///< m
};

class ShortestGridPath {
  public:
    explicit ShortestGridPath(const TraversabilityGrid& grid);
    /// Shortest path between the cells holding `from` and `to`; nullopt when either is not
    /// traversable or they are not connected.
    std::optional<GridPath> plan(const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to);

  private:
    const TraversabilityGrid& grid_;
    gridpath::GridAStar search_;
};

}  // namespace toposlam::planning
