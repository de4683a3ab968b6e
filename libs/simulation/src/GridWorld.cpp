#include <toposlam/simulation/GridWorld.h>
#include <toposlam/simulation/RayDiscIntersection.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::simulation {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

GridWorld::GridWorld(const mrpt::maps::COccupancyGridMap2D& map, const GridWorldOptions& options)
    : geometry_(GridGeometry::of(map)),
      obstacle_(geometry_.cellCount(), 0),
      unknownIsObstacle_(options.unknownIsObstacle) {
    for (int cy = 0; cy < geometry_.sizeY; ++cy) {
        for (int cx = 0; cx < geometry_.sizeX; ++cx) {
            const double p = map.getCell(cx, cy);
            const bool occupied = p < options.thresholds.occupiedBelow;
            const bool unknown = !occupied && p <= options.thresholds.freeAbove;
            obstacle_[geometry_.index(cx, cy)] = occupied || (unknown && unknownIsObstacle_);
        }
    }
}

double GridWorld::castRay(const mrpt::math::TPoint2D& origin, double angle, double maxRange) const {
    const double dx = std::cos(angle), dy = std::sin(angle);
    // Discs first: the nearest one bounds how far the grid traversal has to go.
    double best = kInf;
    for (const Disc& c : discs_) {
        best = std::min(best,
                        rayDiscEntry(origin.x, origin.y, dx, dy, c.centre.x, c.centre.y, c.radius));
    }
    const double limit = std::min(best, maxRange);
    best = std::min(best, castRayGrid(origin.x, origin.y, dx, dy, limit));
    return best <= maxRange ? best : kInf;
}

double GridWorld::castRayGrid(double ox, double oy, double dx, double dy, double maxRange) const {
    const double res = geometry_.resolution;
    // The ray in cell units, relative to the grid's lower-left corner: (u0 + t*dx, v0 + t*dy).
    const double u0 = (ox - geometry_.xMin) / res, v0 = (oy - geometry_.yMin) / res;
    const double tRange = maxRange / res;
    double tStart = 0;
    if (!(u0 >= 0 && v0 >= 0 && u0 < geometry_.sizeX && v0 < geometry_.sizeY)) {
        if (unknownIsObstacle_)
            return 0.0;  // the sensor itself is in unknown space
        // Outside the map with unknown = free: start where the ray enters the grid rectangle.
        double tIn = 0, tOut = kInf;
        const auto slab = [&](double p, double d, double size) {
            if (std::abs(d) < 1e-300)
                return p >= 0 && p < size;
            const double t0 = -p / d, t1 = (size - p) / d;
            tIn = std::max(tIn, std::min(t0, t1));
            tOut = std::min(tOut, std::max(t0, t1));
            return true;
        };
        if (!slab(u0, dx, geometry_.sizeX) || !slab(v0, dy, geometry_.sizeY) || tIn >= tOut ||
            tIn > tRange) {
            return kInf;
        }
        tStart = tIn;
    }
    // Start cell; rays entering from outside are nudged past the rectangle's edge.
    const double tProbe = tStart > 0 ? tStart + 1e-9 : 0.0;
    int cx = std::clamp(static_cast<int>(std::floor(u0 + dx * tProbe)), 0, geometry_.sizeX - 1);
    int cy = std::clamp(static_cast<int>(std::floor(v0 + dy * tProbe)), 0, geometry_.sizeY - 1);
    if (obstacle_[geometry_.index(cx, cy)])
        return tStart * res;

    // Amanatides-Woo: tMaxX / tMaxY = ray parameter of the next vertical / horizontal cell edge.
    const bool movesX = std::abs(dx) > 1e-300, movesY = std::abs(dy) > 1e-300;
    const int stepX = dx > 0 ? 1 : -1, stepY = dy > 0 ? 1 : -1;
    const double tDeltaX = movesX ? 1.0 / std::abs(dx) : kInf;
    const double tDeltaY = movesY ? 1.0 / std::abs(dy) : kInf;
    double tMaxX = movesX ? ((dx > 0 ? cx + 1 : cx) - u0) / dx : kInf;
    double tMaxY = movesY ? ((dy > 0 ? cy + 1 : cy) - v0) / dy : kInf;
    for (;;) {
        double t;
        if (tMaxX < tMaxY) {
            t = tMaxX;
            cx += stepX;
            tMaxX += tDeltaX;
        } else {
            t = tMaxY;
            cy += stepY;
            tMaxY += tDeltaY;
        }
        if (t > tRange)
            return kInf;
        if (!geometry_.contains(cx, cy))
            return unknownIsObstacle_ ? t * res : kInf;
        if (obstacle_[geometry_.index(cx, cy)])
            return t * res;
    }
}

}  // namespace toposlam::simulation
