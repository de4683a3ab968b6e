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
    const mrpt::poses::CPose2D difference = (-lastMotion) + increment;
    if (difference.norm() <= kAgreeDistance &&
        std::abs(mrpt::math::wrapToPi(difference.phi())) <= kAgreeAngle) {
        catchUpLeft_ = 0;  // in step with the robot again
        return false;
    }
    return true;
}

}  // namespace toposlam::mapping
