#pragma once
// A planned room-to-room path: the route through the room graph and the metric polyline.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/planning/RoomRoute.h>

#include <string>
#include <vector>

namespace toposlam::planning {

struct RoomPath {
    bool solved = false;
    std::string failure;  ///< why not, when !solved
    RoomRoute route;
    std::vector<mrpt::math::TPoint2D> points;  ///< the path, world frame (m)
    double length = 0;                         ///< m
    double seconds = 0;                        ///< planning wall time
};

/// Length (m) of a polyline.
double polylineLength(const std::vector<mrpt::math::TPoint2D>& points);

/// Writes a solved path as text: '#' comment lines giving the route, then one "x y" per line
/// (m, world frame). Atomic.
void savePath(const RoomPath& path, const std::string& file);

}  // namespace toposlam::planning
