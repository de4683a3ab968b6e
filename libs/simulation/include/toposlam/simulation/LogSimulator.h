#pragma once
// The simulated robot run: a laser (LaserModel) and wheel odometry (OdometryModel) along a
// ground-truth trajectory over a grid map, with optional people walking about (MovingObstacles);
// written as an MRPT rawlog (either format) plus the ground-truth trajectory file.
#include <mrpt/core/bits_math.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/RawlogWriter.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/GridWorld.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/MovingObstacles.h>
#include <toposlam/simulation/OdometryModel.h>

#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>

namespace toposlam::simulation {

struct LogSimulationOptions {
    LaserModel laser;
    OdometryErrorModel odometry;
    PeopleOptions people;
    GridWorldOptions world;
    /// Odometry is integrated in steps of at most this many metres / radians between scans,
    /// like a real robot's odometry running faster than its laser.
    double odometryStep = 0.05;                     ///< m
    double odometryStepAngle = mrpt::DEG2RAD(2.0);  ///< rad
    unsigned seed = 1;  ///< fixes every random draw: the same inputs give the same log
};

/// Produces the records of a simulated log one by one, in trajectory order.
class LogSimulator {
  public:
    /// `groundTruth`: robot poses (world frame of `map`) with strictly increasing stamps (s).
    /// Throws std::invalid_argument when it is empty or its stamps do not increase.
    LogSimulator(const mrpt::maps::COccupancyGridMap2D& map, io::Trajectory2D groundTruth,
                 const LogSimulationOptions& options);
    ~LogSimulator();

    std::size_t size() const { return groundTruth_.size(); }
    /// Simulates the next record (scan + odometry); false after the last pose.
    /// The record's stamps are the ground-truth stamps rounded to MRPT's 100 ns clock.
    bool next(io::LaserLogRecord& record);
    /// The ground truth with each stamp rounded as the records' are (so they match exactly).
    const io::Trajectory2D& groundTruth() const { return groundTruth_; }
    /// People in the world at the last simulated scan.
    const std::vector<Disc>& people() const { return world_.discs(); }

  private:
    /// The odometry reading of this scan: the integrated odometry, or during a stall the
    /// reading before it.
    mrpt::poses::CPose2D odometryReading();

    LogSimulationOptions options_;
    io::Trajectory2D groundTruth_;
    GridWorld world_;
    ClearanceMap clearance_;
    std::unique_ptr<MovingObstacles> people_;
    OdometryModel odometry_;
    std::mt19937 laserRng_, odometryRng_;
    /// Odometry stalls (OdometryErrorModel::stallProbability): its own draws, so that logs
    /// without stalls stay as they were.
    std::mt19937 stallRng_;
    int stalledScans_ = 0;                 ///< scans the current stall still repeats the reading
    mrpt::poses::CPose2D stalledReading_;  ///< the reading it repeats
    std::size_t next_ = 0;
};

/// Simulates the whole log and writes `rawlogPath` (in `format`; gzip when it ends in .gz) and
/// the ground truth `groundTruthPath` ("timestamp x y yaw", io/Trajectory.h). Both files appear
/// only if everything succeeded. Reports progress after every scan (scans written).
/// Returns the number of scans written.
std::size_t simulateLogToFiles(const mrpt::maps::COccupancyGridMap2D& map,
                               const io::Trajectory2D& groundTruth,
                               const LogSimulationOptions& options, const std::string& rawlogPath,
                               io::RawlogFormat format, const std::string& groundTruthPath,
                               const io::ProgressCallback& progress = {});

}  // namespace toposlam::simulation
