#pragma once
// Small maps and exact geometry helpers shared by the simulation tests.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/simulation/FloorPlan.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::simulation::test {

/// Distance (m) from `p` to the nearest point of a solid of `plan` (wall pieces, furniture).
inline double distanceToSolid(const FloorPlan& plan, const mrpt::math::TPoint2D& p) {
    double best = std::numeric_limits<double>::infinity();
    const auto boxDistance = [&](const Box& b) {
        const double dx = std::max({b.xMin - p.x, 0.0, p.x - b.xMax});
        const double dy = std::max({b.yMin - p.y, 0.0, p.y - b.yMax});
        best = std::min(best, std::hypot(dx, dy));
    };
    for (const Box& b : plan.wallPieces())
        boxDistance(b);
    for (const Box& b : plan.furnitureBoxes())
        boxDistance(b);
    for (const Disc& d : plan.furnitureDiscs()) {
        best = std::min(best,
                        std::max(0.0, std::hypot(p.x - d.centre.x, p.y - d.centre.y) - d.radius));
    }
    return best;
}

/// A closed rectangular room: floor [0,w] x [0,h], walls `thickness` thick outside it.
inline FloorPlan boxRoom(double w, double h, double thickness = 0.1) {
    FloorPlan plan;
    const double t = thickness, o = thickness / 2;
    plan.addWall({-t, -o}, {w + t, -o}, t);
    plan.addWall({-t, h + o}, {w + t, h + o}, t);
    plan.addWall({-o, -t}, {-o, h + t}, t);
    plan.addWall({w + o, -t}, {w + o, h + t}, t);
    plan.addRoom("room", "room", {0, 0, w, h});
    return plan;
}

}  // namespace toposlam::simulation::test
