#include <toposlam/mapping/OdometryLag.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace toposlam::mapping {

bool OdometryLag::catchingUp(const mrpt::poses::CPose2D& increment,
                             const mrpt::poses::CPose2D& lastMotion) {
    if (increment.x() == 0 && increment.y() == 0 && increment.phi() == 0) {
        stalled_ = lastMotion.norm() > kMovedDistance ||
                   std::abs(mrpt::math::wrapToPi(lastMotion.phi())) > kMovedAngle;
        return false;
    }
    if (stalled_) {
        stalled_ = false;
        catchUpLeft_ = kMaxCatchUpScans;
    }
    if (catchUpLeft_ == 0)
        return false;
    --catchUpLeft_;
    // A backlog adds to the motion: a step that is not longer, nor turns farther, than the last
    // registered one by the margins is the odometry in step with the robot again (one that
    // reads less is the robot slowing down, which at a low scan rate is a large change too).
    const double longer = increment.norm() - lastMotion.norm();
    const double farther = std::abs(mrpt::math::wrapToPi(increment.phi())) -
                           std::abs(mrpt::math::wrapToPi(lastMotion.phi()));
    if (longer <= kAgreeDistance && farther <= kAgreeAngle) {
        catchUpLeft_ = 0;
        return false;
    }
    return true;
}

}  // namespace toposlam::mapping
