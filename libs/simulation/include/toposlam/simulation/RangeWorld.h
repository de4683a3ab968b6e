#pragma once
// What a simulated laser sees: anything that can answer "how far along this ray is the first
// obstacle". Implemented by PolygonWorld (exact vector geometry, for ground-truth corners and
// segments) and GridWorld (an occupancy grid map, for whole floor plans).
#include <mrpt/math/TPoint2D.h>

namespace toposlam::simulation {

class RangeWorld {
  public:
    virtual ~RangeWorld() = default;
    /// Distance (m) from `origin` (world frame, m) along direction `angle` (rad, world frame)
    /// to the first obstacle, or +infinity when nothing is hit within `maxRange` (m).
    virtual double castRay(const mrpt::math::TPoint2D& origin, double angle,
                           double maxRange) const = 0;
};

}  // namespace toposlam::simulation
