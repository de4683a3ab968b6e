#pragma once
// How the simulated robot drives a planned path and when its laser records. The robot follows
// each leg with its heading along the path tangent, at most maxSpeed, slowing down where the
// path turns faster than maxTurnRate allows; between legs it turns on the spot. Like the loggers
// of real robots (CARMEN, MRPT's rawlog-grabber with a motion filter), it records a scan each
// time it has driven scanDistance or turned scanAngle since the last one.
#include <mrpt/core/bits_math.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/io/Trajectory.h>

#include <vector>

namespace toposlam::simulation {

struct MotionOptions {
    double maxSpeed = 0.4;                     ///< m/s
    double maxTurnRate = mrpt::DEG2RAD(30.0);  ///< rad/s
    double scanDistance = 0.3;                 ///< m driven between recorded scans
    double scanAngle = mrpt::DEG2RAD(15.0);    ///< rad turned between recorded scans
    double startTime = 1700000000.0;           ///< s (Unix time) of the first scan

    /// Keys max_speed, max_turn_rate_deg, scan_distance, scan_angle_deg, start_time (part of
    /// [Tour], see TourOptions).
    void declare(config::OptionsSchema& s);
};

/// The timed robot poses (world frame; stamps in s) at which scans are recorded while driving
/// `legs` one after the other. Each leg is a polyline (world frame, m) that starts where the
/// previous one ended; the robot starts at the first point of the first leg with heading
/// `initialYaw` (rad). The first and the last pose are always recorded.
io::Trajectory2D driveLegs(const std::vector<std::vector<mrpt::math::TPoint2D>>& legs,
                           double initialYaw, const MotionOptions& options);

}  // namespace toposlam::simulation
