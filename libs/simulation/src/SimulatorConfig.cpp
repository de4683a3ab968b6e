#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include "ConfigReading.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace toposlam::simulation {

using mrpt::DEG2RAD;

LogSimulationOptions SimulatorConfig::defaultLog() {
    LogSimulationOptions o;
    o.laser.beams = 361;
    o.laser.aperture = DEG2RAD(270.0);
    o.laser.maxRange = 20.0;
    o.laser.minRange = 0.05;
    o.laser.rangeNoiseStd = 0.01;
    o.laser.bearingNoiseStd = DEG2RAD(0.05);
    o.laser.sensorPose = mrpt::poses::CPose3D(0.2, 0.0, 0.3, 0, 0, 0);
    o.laser.sensorLabel = "LASER";
    return o;
}

io::RawlogFormat parseRawlogFormat(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
    if (n == "sf" || n == "sensoryframes")
        return io::RawlogFormat::SensoryFrames;
    if (n == "obs" || n == "observations")
        return io::RawlogFormat::Observations;
    throw std::invalid_argument("unknown rawlog format '" + name + "' (use sf or obs)");
}

void loadSimulatorConfig(const mrpt::config::CConfigFileBase& c, SimulatorConfig& config) {
    LaserModel& l = config.log.laser;
    const std::string laser = "Laser";
    l.beams = static_cast<std::size_t>(c.read_uint64_t(laser, "beams", l.beams));
    detail::readDegrees(c, laser, "fov_deg", l.aperture);
    detail::readKey(c, laser, "max_range", l.maxRange);
    detail::readKey(c, laser, "min_range", l.minRange);
    detail::readKey(c, laser, "range_noise", l.rangeNoiseStd);
    detail::readDegrees(c, laser, "bearing_noise_deg", l.bearingNoiseStd);
    l.rightToLeft = c.read_bool(laser, "right_to_left", l.rightToLeft);
    l.sensorLabel = c.read_string(laser, "label", l.sensorLabel);
    double x = l.sensorPose.x(), y = l.sensorPose.y(), z = l.sensorPose.z(),
           yaw = l.sensorPose.yaw();
    detail::readKey(c, laser, "sensor_x", x);
    detail::readKey(c, laser, "sensor_y", y);
    detail::readKey(c, laser, "sensor_z", z);
    detail::readDegrees(c, laser, "sensor_yaw_deg", yaw);
    l.sensorPose = mrpt::poses::CPose3D(x, y, z, yaw, 0, 0);

    config.log.odometry.loadFromConfig(c, "Odometry");
    config.log.people.loadFromConfig(c, "People");
    config.tour.loadFromConfig(c, "Tour");

    const std::string sim = "Simulation";
    config.log.seed = static_cast<unsigned>(c.read_uint64_t(sim, "seed", config.log.seed));
    detail::readKey(c, sim, "odometry_step", config.log.odometryStep);
    detail::readDegrees(c, sim, "odometry_step_deg", config.log.odometryStepAngle);
    detail::readKey(c, sim, "occupied_below", config.log.world.thresholds.occupiedBelow);
    detail::readKey(c, sim, "free_above", config.log.world.thresholds.freeAbove);
    config.log.world.unknownIsObstacle =
        c.read_bool(sim, "unknown_is_obstacle", config.log.world.unknownIsObstacle);
    const std::string format = c.read_string(sim, "format", "");
    if (!format.empty())
        config.format = parseRawlogFormat(format);
}

void validate(const SimulatorConfig& config) {
    const auto require = [](bool ok, const std::string& what) {
        if (!ok)
            throw std::invalid_argument(what);
    };
    const LaserModel& l = config.log.laser;
    require(l.beams >= 2, "the laser needs at least 2 beams");
    require(l.aperture > 0 && l.aperture <= 2 * M_PI + 1e-9,
            "the field of view must be in (0, 360] deg");
    require(l.maxRange > 0 && l.minRange >= 0 && l.minRange < l.maxRange,
            "laser ranges: need 0 <= min range < max range");
    require(l.rangeNoiseStd >= 0 && l.bearingNoiseStd >= 0, "noise must not be negative");
    const OdometryErrorModel& o = config.log.odometry;
    require(o.distanceScale > 0 && o.rotationScale > 0, "odometry scales must be positive");
    require(o.alpha1 >= 0 && o.alpha2 >= 0 && o.alpha3 >= 0 && o.alpha4 >= 0,
            "odometry noise must not be negative");
    const PeopleOptions& p = config.log.people;
    require(p.radius > 0 && p.minSpeed > 0 && p.maxSpeed >= p.minSpeed && p.maxPause >= 0,
            "people: need radius > 0 and 0 < min speed <= max speed, pause >= 0");
    const TourOptions& t = config.tour;
    require(t.robotRadius > 0 && t.safetyMargin >= 0, "robot radius must be positive");
    require(t.motion.maxSpeed > 0 && t.motion.maxTurnRate > 0,
            "max speed and max turn rate must be positive");
    require(t.motion.scanDistance > 0 && t.motion.scanAngle > 0,
            "scan distance and scan angle must be positive");
    require(config.log.odometryStep > 0 && config.log.odometryStepAngle > 0,
            "odometry steps must be positive");
    require(config.log.world.thresholds.occupiedBelow <= config.log.world.thresholds.freeAbove,
            "occupied_below must not exceed free_above");
}

}  // namespace toposlam::simulation
