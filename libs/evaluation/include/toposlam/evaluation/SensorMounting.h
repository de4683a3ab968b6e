#pragma once
// Where the laser sits on the robot, estimated from the data: planar hand-eye calibration of a
// trajectory of SENSOR poses (a SLAM result) against the log's wheel odometry (ROBOT poses).
// Over pairs of scans a few apart, the odometry says how the robot moved (A, in the robot's
// frame) and the trajectory how the sensor moved (B, in the sensor's frame); with X the
// sensor's pose on the robot, A (+) X = X (+) B. The rotation part only says that both turned
// alike; the translation part, with odometry distances s times the trajectory's,
//     (R_A - I) s t_X - s R_X t_B = -t_A,
// is linear in (s t_x, s t_y, s cos(yaw_X), s sin(yaw_X)). Only pairs that turn fix t_X (a
// straight drive says nothing about where on the robot the sensor is), so pairs turning less
// than minTurn are left out. Solved by linear least squares, then once more without the pairs
// beyond 3 sigma (wheel slip).
// What it is for: checking the frame a trajectory is in. A trajectory of the robot's own poses
// gives (0, 0, 0); one of the laser's poses gives the laser's mounting as the odometry sees it.
#include <mrpt/math/TPose2D.h>
#include <toposlam/io/Trajectory.h>

#include <cstddef>
#include <optional>

namespace toposlam::evaluation {

struct SensorMountingOptions {
    std::size_t pairStep = 5;           ///< a pair joins the scans this many poses apart
    double minTurn = 0.05;              ///< rad (2.9 deg): pairs that turn less are left out
    double maxTurnDisagreement = 0.05;  ///< rad: the two turns differ more: a slip, left out
    double maxMotion = 1.0;  ///< m: odometry moving more within a pair is a jump, left out
};

struct SensorMounting {
    /// The sensor's pose on the robot (x forward, y left, m; phi rad): robot (+) mounting =
    /// sensor.
    mrpt::math::TPose2D mounting;
    double odometryScale = 1;  ///< s: odometry distance per trajectory distance
    std::size_t pairs = 0;     ///< turning pairs used in the final solve
    double residualRms = 0;    ///< m, of the translation equations over those pairs
    /// m, standard deviations of the mounting's x, y (least squares, widened by sqrt(pairStep)
    /// because overlapping pairs share their poses' errors).
    double stdX = 0, stdY = 0;
};

/// `odometry`: the log's odometry at each scan (e.g. odometryAtScans); `sensorPoses`: the
/// trajectory to check. Poses are paired by stamp (within `stampTolerance` s), pairs formed in
/// the trajectory's order. nullopt when fewer than 10 turning pairs are available.
std::optional<SensorMounting> estimateSensorMounting(const io::Trajectory2D& odometry,
                                                     const io::Trajectory2D& sensorPoses,
                                                     double stampTolerance,
                                                     const SensorMountingOptions& options = {});

}  // namespace toposlam::evaluation
