#include <toposlam/io/MirrorImage.h>

#include <memory>

namespace toposlam::io {

mrpt::math::TPose2D mirroredPose(const mrpt::math::TPose2D& pose) {
    return {pose.x, -pose.y, -pose.phi};
}

mrpt::poses::CPose2D mirroredPose(const mrpt::poses::CPose2D& pose) {
    return mrpt::poses::CPose2D(pose.x(), -pose.y(), -pose.phi());
}

Trajectory2D mirroredTrajectory(const Trajectory2D& trajectory) {
    Trajectory2D out;
    out.reserve(trajectory.size());
    for (const TimedPose2D& p : trajectory)
        out.push_back({p.stamp, mirroredPose(p.pose)});
    return out;
}

mrpt::obs::CObservation2DRangeScan::Ptr mirroredScan(
    const mrpt::obs::CObservation2DRangeScan& scan) {
    auto out = std::make_shared<mrpt::obs::CObservation2DRangeScan>(scan);
    const std::size_t n = scan.getScanSize();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t from = n - 1 - i;
        out->setScanRange(i, scan.getScanRange(from));
        out->setScanRangeValidity(i, scan.getScanRangeValidity(from));
        if (scan.hasIntensity())
            out->setScanIntensity(i, scan.getScanIntensity(from));
    }
    // The reflection S = diag(1, -1, 1) turns the sensor's rotation R into S R S, which for
    // R = Rz(yaw) Ry(pitch) Rx(roll) is Rz(-yaw) Ry(pitch) Rx(-roll); a reading at angle a in
    // the sensor's plane then lands where the reading at -a did, mirrored.
    const mrpt::poses::CPose3D& p = scan.sensorPose;
    out->sensorPose = mrpt::poses::CPose3D(p.x(), -p.y(), p.z(), -p.yaw(), p.pitch(), -p.roll());
    return out;
}

}  // namespace toposlam::io
