#include <toposlam/simulation/LaserModel.h>

#include <cmath>

namespace toposlam::simulation {

mrpt::obs::CObservation2DRangeScan simulateScan(const RangeWorld& world, const LaserModel& laser,
                                                const mrpt::poses::CPose2D& robotPose,
                                                std::mt19937& rng) {
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(laser.aperture);
    scan.rightToLeft = laser.rightToLeft;
    scan.maxRange = static_cast<float>(laser.maxRange);
    scan.sensorPose = laser.sensorPose;
    scan.sensorLabel = laser.sensorLabel;
    scan.stdError = static_cast<float>(laser.rangeNoiseStd);
    scan.resizeScan(laser.beams);

    const mrpt::poses::CPose3D sensorInWorld = mrpt::poses::CPose3D(robotPose) + laser.sensorPose;
    const mrpt::math::TPoint2D origin(sensorInWorld.x(), sensorInWorld.y());
    std::normal_distribution<double> rangeNoise(0.0, laser.rangeNoiseStd);
    std::normal_distribution<double> bearingNoise(0.0, laser.bearingNoiseStd);

    for (std::size_t i = 0; i < laser.beams; ++i) {
        double bearing = scan.getScanAngle(i);
        if (laser.bearingNoiseStd > 0)
            bearing += bearingNoise(rng);
        double r = world.castRay(origin, sensorInWorld.yaw() + bearing, laser.maxRange);
        if (std::isfinite(r) && laser.rangeNoiseStd > 0)
            r += rangeNoise(rng);
        const bool valid = std::isfinite(r) && r >= laser.minRange && r < laser.maxRange;
        scan.setScanRange(i, valid ? static_cast<float>(r) : scan.maxRange);
        scan.setScanRangeValidity(i, valid);
    }
    return scan;
}

}  // namespace toposlam::simulation
