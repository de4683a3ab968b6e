#include <mrpt/core/bits_math.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <toposlam/config/IniFile.h>

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

TourOptions plannedTour(const SimulatorConfig& config) {
    TourOptions tour = config.tour;
    tour.coverage.viewRange = std::min(tour.coverage.viewRange, config.log.laser.maxRange);
    return tour;
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

const std::vector<std::string>& SimulatorConfig::sections() {
    static const std::vector<std::string> names = {"Laser", "Odometry", "People", "Tour",
                                                   "Simulation"};
    return names;
}

void SimulatorConfig::declare(config::OptionsSchema& s) {
    s.choice("format", format,
             {{"obs", io::RawlogFormat::Observations}, {"sf", io::RawlogFormat::SensoryFrames}},
             "rawlog format: obs = CObservationOdometry + CObservation2DRangeScan; sf = actions + "
             "sensory frames");
    s.integer("seed", log.seed, "",
              "random seed: the same map, trajectory, configuration and seed give the same log");
    s.real("odometry_step", log.odometryStep, "m",
           "odometry is integrated in steps of at most this length between scans")
        .above(0);
    s.angle("odometry_step", log.odometryStepAngle, "... and at most this angle").above(0);
    s.real("occupied_below", log.world.thresholds.occupiedBelow, "",
           "map cells with p(free) below this are walls")
        .within(0, 1);
    s.real("free_above", log.world.thresholds.freeAbove, "",
           "cells with p(free) above this are free, in between unknown")
        .within(0, 1);
    s.require(
        [this] { return log.world.thresholds.occupiedBelow <= log.world.thresholds.freeAbove; },
        "occupied_below", "must not exceed free_above");
    s.flag("unknown_is_obstacle", log.world.unknownIsObstacle,
           "unknown cells (and the map's edge) stop the laser");
}

void loadSimulatorConfig(const mrpt::config::CConfigFileBase& c, SimulatorConfig& config) {
    config::requireKnownSections(c, SimulatorConfig::sections());
    config.log.laser.loadFromConfigFile(c, "Laser");
    config.log.odometry.loadFromConfigFile(c, "Odometry");
    config.log.people.loadFromConfigFile(c, "People");
    config.tour.loadFromConfigFile(c, "Tour");
    config.loadFromConfigFile(c, "Simulation");
}

void validate(const SimulatorConfig& config) {
    config.log.laser.validate("Laser");
    config.log.odometry.validate("Odometry");
    config.log.people.validate("People");
    config.tour.validate("Tour");
    config.validate("Simulation");
}

}  // namespace toposlam::simulation
