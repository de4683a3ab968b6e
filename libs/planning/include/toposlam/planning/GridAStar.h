#pragma once
// The reference shortest path: A* over the 8-connected traversable cells of a
// TraversabilityGrid (diagonal steps cost sqrt(2) cells, and may not cut a blocked corner).
// It is what sampling-based plans are compared with: optimal on the grid, but its length
// includes the grid's staircase (up to ~8 % longer than the true shortest path).
#include <mrpt/math/TPoint2D.h>
#include <toposlam/planning/TraversabilityGrid.h>

#include <optional>
#include <vector>

namespace toposlam::planning {

struct GridPath {
    std::vector<mrpt::math::TPoint2D> points;  ///< cell centres, world frame (m)
    double length = 0;                         ///< m
};

class GridAStar {
  public:
    explicit GridAStar(const TraversabilityGrid& grid);
    /// Shortest path between the cells holding `from` and `to`; nullopt when either is not
    /// traversable or they are not connected.
    std::optional<GridPath> plan(const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to);

  private:
    const TraversabilityGrid& grid_;
    // Per-cell search state, kept between queries (no allocation per query).
    std::vector<float> cost_;
    std::vector<int> parent_;
    std::vector<unsigned> visitedStamp_;
    unsigned stamp_ = 0;
};

}  // namespace toposlam::planning
