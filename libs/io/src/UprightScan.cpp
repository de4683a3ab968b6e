#include <toposlam/io/UprightScan.h>

#include <cmath>

namespace toposlam::io {

namespace {
// cos(5 deg): how close the laser's z axis must come to pointing straight down.
constexpr double kUpsideDownCos = 0.9961946980917455;
}  // namespace

bool isUpsideDown(const mrpt::obs::CObservation2DRangeScan& scan) {
    return scan.sensorPose.getRotationMatrix()(2, 2) <= -kUpsideDownCos;
}

bool makeUpright(mrpt::obs::CObservation2DRangeScan& scan) {
    if (!isUpsideDown(scan))
        return false;
    const auto R = scan.sensorPose.getRotationMatrix();
    // With the z axis pointing down, the rotation maps the scan plane's direction a to
    // yaw - a, where yaw is the direction of the laser's x axis: a mirror image of the
    // plane, i.e. the upright sweep in the other direction.
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    const auto& p = scan.sensorPose;
    scan.sensorPose = mrpt::poses::CPose3D(p.x(), p.y(), p.z(), yaw, 0.0, 0.0);
    scan.rightToLeft = !scan.rightToLeft;
    return true;
}

mrpt::obs::CObservation2DRangeScan::Ptr uprightScan(
    const mrpt::obs::CObservation2DRangeScan::Ptr& scan) {
    if (!scan || !isUpsideDown(*scan))
        return scan;
    auto upright = std::make_shared<mrpt::obs::CObservation2DRangeScan>(*scan);
    makeUpright(*upright);
    return upright;
}

}  // namespace toposlam::io
