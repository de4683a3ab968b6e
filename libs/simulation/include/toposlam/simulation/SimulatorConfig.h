#pragma once
// Every parameter of toposlam-sim in one place, with the defaults of config_ini/sim-office.ini
// (the configuration of share/office's log), and how they are read from an .ini file.
#include <toposlam/io/RawlogWriter.h>
#include <toposlam/simulation/LogSimulator.h>
#include <toposlam/simulation/TourPlanner.h>

#include <string>

namespace mrpt::config {
class CConfigFileBase;
}

namespace toposlam::simulation {

struct SimulatorConfig {
    /// Laser: a Hokuyo UTM-30LX-class scanner (270 deg, 1 cm range noise) read out at 0.75 deg,
    /// 0.2 m ahead of the robot's centre and 0.3 m above the floor; odometry: see
    /// OdometryErrorModel; no people.
    LogSimulationOptions log = defaultLog();
    TourOptions tour;
    io::RawlogFormat format = io::RawlogFormat::Observations;

    static LogSimulationOptions defaultLog();
};

/// Reads the sections [Laser], [Odometry], [People], [Tour], [Simulation] (keys documented in
/// config_ini/sim-office.ini) into `config`; absent keys keep their values. Throws
/// std::invalid_argument for values out of range (e.g. fewer than 2 beams, an unknown format).
void loadSimulatorConfig(const mrpt::config::CConfigFileBase& ini, SimulatorConfig& config);

/// Checks ranges of the values a user can set (beams >= 2, 0 < aperture <= 2 pi, ranges > 0,
/// noise >= 0, speeds > 0, ...); throws std::invalid_argument naming the offending parameter.
void validate(const SimulatorConfig& config);

/// "sf" / "obs" (also the enum names' spellings "sensoryframes" / "observations").
io::RawlogFormat parseRawlogFormat(const std::string& name);

}  // namespace toposlam::simulation
