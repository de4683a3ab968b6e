#pragma once
// Where a ray first enters a disc; shared by the vector and the grid worlds (people, pillars).
#include <cmath>
#include <limits>

namespace toposlam::simulation {

/// Distance along the unit direction (dx, dy) from (ox, oy) to where the ray enters the disc of
/// centre (cx, cy) and radius r (all m); +infinity when it misses, or when the origin is inside
/// the disc (a sensor inside an obstacle sees nothing of it).
inline double rayDiscEntry(double ox, double oy, double dx, double dy, double cx, double cy,
                           double r) {
    const double px = ox - cx, py = oy - cy;
    const double b = px * dx + py * dy;
    const double disc = b * b - (px * px + py * py - r * r);
    if (disc < 0)
        return std::numeric_limits<double>::infinity();
    const double t = -b - std::sqrt(disc);
    return t > 0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace toposlam::simulation
