#pragma once
// A RangeWorld made of an occupancy grid map (whole floor plans, maps built by SLAM), plus
// optional discs on top of it (people, moving obstacles). Ray casting is exact with respect to
// the cells: each ray visits every cell it crosses (Amanatides & Woo, "A fast voxel traversal
// algorithm", 1987) and returns the distance to the edge of the first obstacle cell.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/GridGeometry.h>
#include <toposlam/simulation/PolygonWorld.h>
#include <toposlam/simulation/RangeWorld.h>

#include <cstdint>
#include <vector>

namespace toposlam::simulation {

struct GridWorldOptions {
    OccupancyThresholds thresholds;
    /// Whether cells of unknown occupancy (and everything outside the map) stop the laser. True
    /// by default: behind the edge of a mapped area there is usually a wall the map missed, and
    /// a return there is more realistic than a max-range reading through unexplored space.
    bool unknownIsObstacle = true;
};

class GridWorld : public RangeWorld {
  public:
    explicit GridWorld(const mrpt::maps::COccupancyGridMap2D& map,
                       const GridWorldOptions& options = {});

    const GridGeometry& geometry() const { return geometry_; }
    /// Whether the laser stops in cell (cx, cy); cells outside the map count as unknown.
    bool isObstacle(int cx, int cy) const {
        return geometry_.contains(cx, cy) ? obstacle_[geometry_.index(cx, cy)] != 0
                                          : unknownIsObstacle_;
    }

    /// Discs on top of the grid (people); move them between scans.
    std::vector<Disc>& discs() { return discs_; }
    const std::vector<Disc>& discs() const { return discs_; }

    /// Distance (m) to the first obstacle cell edge or disc along the ray; 0 when `origin` is in
    /// an obstacle cell; +infinity when nothing is hit within `maxRange`.
    double castRay(const mrpt::math::TPoint2D& origin, double angle,
                   double maxRange) const override;

  private:
    double castRayGrid(double ox, double oy, double dx, double dy, double maxRange) const;

    GridGeometry geometry_;
    std::vector<std::uint8_t> obstacle_;
    bool unknownIsObstacle_;
    std::vector<Disc> discs_;
};

}  // namespace toposlam::simulation
