#include <toposlam/simulation/LaserModel.h>

#include <cmath>

namespace toposlam::simulation {

void LaserModel::declare(config::OptionsSchema& s) {
    // Beam counts beyond any real 2D laser would only exhaust memory (4e9 beams: 24 GB).
    s.integer("beams", beams, "", "readings per scan, spread evenly over the field of view")
        .within(2, 100000);
    s.angle("fov", aperture, "angle from the first to the last beam, counter-clockwise")
        .above(0)
        .atMost(360);
    s.real("max_range", maxRange, "m", "returns beyond are invalid readings").above(0);
    s.real("min_range", minRange, "m", "returns nearer than this are invalid readings").atLeast(0);
    s.require([this] { return minRange < maxRange; }, "min_range", "must be below max_range");
    s.real("range_noise", rangeNoiseStd, "m", "Gaussian range noise, 1 sigma").atLeast(0);
    s.angle("bearing_noise", bearingNoiseStd, "Gaussian noise of each beam's direction, 1 sigma")
        .atLeast(0);
    s.flag("right_to_left", rightToLeft, "beam order counter-clockwise (MRPT's convention)");
    s.text("label", sensorLabel, "sensor label of the scans in the rawlog");
    s.real("sensor_x", sensorPose.x(), "m", "laser position on the robot: ahead of its centre");
    s.real("sensor_y", sensorPose.y(), "m", "... to the left");
    s.real("sensor_z", sensorPose.z(), "m", "... above the floor");
    s.computedAngle(
        "sensor_yaw", [this] { return sensorPose.yaw(); },
        [this](double yaw) {
            sensorPose.setYawPitchRoll(yaw, sensorPose.pitch(), sensorPose.roll());
        },
        "laser direction on the robot (counter-clockwise from ahead)");
}

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
