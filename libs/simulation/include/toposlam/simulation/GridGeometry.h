#pragma once
// The cell layout of an occupancy grid, shared by every raster the simulator derives from a
// map (obstacle masks, clearance, labels). Cell (cx, cy) covers
// [xMin + cx*resolution, xMin + (cx+1)*resolution) x [yMin + cy*resolution, ...) in the map's
// world frame (m); rasters are stored row by row, cy = 0 first (lowest y).
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <cmath>
#include <cstddef>

namespace toposlam::simulation {

struct GridGeometry {
    int sizeX = 0, sizeY = 0;   ///< cells
    double resolution = 0.05;   ///< m per cell
    double xMin = 0, yMin = 0;  ///< m, world position of the lower-left corner of cell (0,0)

    static GridGeometry of(const mrpt::maps::COccupancyGridMap2D& map) {
        GridGeometry g;
        g.sizeX = static_cast<int>(map.getSizeX());
        g.sizeY = static_cast<int>(map.getSizeY());
        g.resolution = map.getResolution();
        g.xMin = map.getXMin();
        g.yMin = map.getYMin();
        return g;
    }

    std::size_t cellCount() const {
        return static_cast<std::size_t>(sizeX) * static_cast<std::size_t>(sizeY);
    }
    bool contains(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < sizeX && cy < sizeY; }
    std::size_t index(int cx, int cy) const {
        return static_cast<std::size_t>(cy) * static_cast<std::size_t>(sizeX) +
               static_cast<std::size_t>(cx);
    }
    int cellX(double x) const { return static_cast<int>(std::floor((x - xMin) / resolution)); }
    int cellY(double y) const { return static_cast<int>(std::floor((y - yMin) / resolution)); }
    /// World position (m) of the centre of cell (cx, cy).
    mrpt::math::TPoint2D centre(int cx, int cy) const {
        return {xMin + (cx + 0.5) * resolution, yMin + (cy + 0.5) * resolution};
    }
    mrpt::math::TPoint2D centre(std::size_t index) const {
        return centre(static_cast<int>(index % static_cast<std::size_t>(sizeX)),
                      static_cast<int>(index / static_cast<std::size_t>(sizeX)));
    }
};

}  // namespace toposlam::simulation
