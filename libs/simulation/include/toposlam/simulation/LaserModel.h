#pragma once
// A 2D laser range finder: beam layout, range limit and noise, and scan simulation against
// any RangeWorld. Beam i points at -aperture/2 + i*aperture/(beams-1) in the sensor frame
// (MRPT's convention, counter-clockwise when rightToLeft).
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <toposlam/config/Options.h>
#include <toposlam/simulation/RangeWorld.h>

#include <cstddef>
#include <random>
#include <string>

namespace toposlam::simulation {

/// Section [Laser] of config_ini/sim-office.ini.
struct LaserModel : public config::Options {
    std::size_t beams = 361;
    double aperture = M_PI;      ///< rad, angle from the first to the last beam
    double maxRange = 30.0;      ///< m; farther (or no) returns are invalid readings
    double minRange = 0.05;      ///< m; nearer returns are invalid readings
    double rangeNoiseStd = 0;    ///< m, Gaussian, per beam
    double bearingNoiseStd = 0;  ///< rad, Gaussian jitter of each beam's true direction
    bool rightToLeft = true;
    mrpt::poses::CPose3D sensorPose;  ///< laser pose in the robot frame
    std::string sensorLabel = "LASER";

    void declare(config::OptionsSchema& s) override;
};

/// Simulates one scan taken with the robot at `robotPose` (world frame). The returned scan
/// has the model's geometry, its sensorPose and label; no timestamp is set. Invalid beams
/// (no return within [minRange, maxRange]) have range maxRange and validity 0.
/// `rng` supplies the noise; pass any engine (its state advances).
mrpt::obs::CObservation2DRangeScan simulateScan(const RangeWorld& world, const LaserModel& laser,
                                                const mrpt::poses::CPose2D& robotPose,
                                                std::mt19937& rng);

}  // namespace toposlam::simulation
