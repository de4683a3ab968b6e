#pragma once
// Every parameter of toposlam-sim in one place, with the defaults of config_ini/sim-office.ini
// (the configuration of share/office's log), and how they are read from an .ini file: one
// config::Options struct per section, [Laser] LaserModel, [Odometry] OdometryErrorModel,
// [People] PeopleOptions, [Tour] TourOptions, and [Simulation] this struct's own keys.
#include <toposlam/config/Options.h>
#include <toposlam/io/RawlogWriter.h>
#include <toposlam/simulation/LogSimulator.h>
#include <toposlam/simulation/TourPlanner.h>

#include <string>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
}

namespace toposlam::simulation {

struct SimulatorConfig : public config::Options {
    /// Laser: a Hokuyo UTM-30LX-class scanner (270 deg, 1 cm range noise) read out at 0.75 deg,
    /// 0.2 m ahead of the robot's centre and 0.3 m above the floor; odometry: see
    /// OdometryErrorModel; no people.
    LogSimulationOptions log = defaultLog();
    TourOptions tour;
    io::RawlogFormat format = io::RawlogFormat::Observations;

    static LogSimulationOptions defaultLog();
    /// The sections of a simulator .ini file.
    static const std::vector<std::string>& sections();
    /// [Simulation]: format, seed, odometry steps, occupancy thresholds of the map.
    void declare(config::OptionsSchema& s) override;
};

/// Reads the sections of SimulatorConfig::sections() (keys documented in
/// config_ini/sim-office.ini) into `config`; absent keys keep their values. Throws
/// config::ConfigError for an unknown section or key, or a bad value.
void loadSimulatorConfig(const mrpt::config::CConfigFileBase& ini, SimulatorConfig& config);

/// Checks every value against its declared range (beams >= 2, 0 < field of view <= 360 deg,
/// 0 <= min range < max range, noise >= 0, speeds > 0, ...); throws config::ConfigError naming
/// the section and key.
void validate(const SimulatorConfig& config);

/// The tour of `config` as it is planned: [Tour] with view_range cut to the laser's max_range
/// (a 3.5 m laser does not see what lies 5 m away, and a tour that counted it seen would
/// leave it unmapped).
TourOptions plannedTour(const SimulatorConfig& config);

/// "sf" / "obs" (also the enum names' spellings "sensoryframes" / "observations").
io::RawlogFormat parseRawlogFormat(const std::string& name);

}  // namespace toposlam::simulation
