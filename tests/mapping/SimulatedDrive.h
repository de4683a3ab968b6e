#pragma once
// Simulated robot drives for the SLAM tests: a path through a vector world, the laser scans
// along it (exact ray casting, Gaussian range noise) and wheel odometry with the usual
// systematic errors, so every estimate can be compared with the exact truth.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <string>
#include <vector>

namespace toposlam::test {

/// Poses every `step` metres along the polyline through `waypoints`, facing along it; at each
/// waypoint the robot turns on the spot in steps of at most `turnStep` rad.
std::vector<mrpt::poses::CPose2D> drivePath(const std::vector<mrpt::math::TPoint2D>& waypoints,
                                            double step = 0.1, double turnStep = 0.17);

struct OdometryErrors {
    double distanceScale = 1.0;       ///< over-read of distance
    double turnScale = 1.0;           ///< over-read of turns
    double headingDriftPerMetre = 0;  ///< rad of heading error per metre driven
    /// From scan `jumpAt` on, the odometry is offset by `jump` (a glitch); 0 = none.
    std::size_t jumpAt = 0;
    mrpt::poses::CPose2D jump;
    /// Driving backwards is counted as driving forward (as fr079's odometry does).
    bool reversingReadsForward = false;
};

struct SimulatedDrive {
    std::vector<mrpt::poses::CPose2D> truth;
    std::vector<mrpt::poses::CPose2D> odometry;  ///< cumulative
    std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
};

/// Scans (361 beams over 180 deg, 20 m, 1 cm noise unless `laser` says otherwise) and
/// odometry along `truth`; stamps 10 Hz from t = 1000 s.
SimulatedDrive simulateDrive(const simulation::PolygonWorld& world,
                             const std::vector<mrpt::poses::CPose2D>& truth,
                             const OdometryErrors& errors, unsigned seed = 1,
                             const simulation::LaserModel& laser = {});

/// Writes the drive as an observations-format rawlog.
void writeRawlog(const SimulatedDrive& drive, const std::string& path);

/// Root-mean-square position error after the best rigid alignment of `estimate` to `truth`.
double absoluteTrajectoryError(const std::vector<mrpt::poses::CPose2D>& truth,
                               const std::vector<mrpt::poses::CPose2D>& estimate);

}  // namespace toposlam::test
