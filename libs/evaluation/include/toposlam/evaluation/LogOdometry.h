#pragma once
// What a laser log itself says about the robot's path: its raw wheel odometry at each scan,
// and each scan's stamp as the file prints it (the stamps relation files use) with the laser's
// position on the robot. The odometry-only trajectory is the baseline every SLAM result is
// compared with.
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/Trajectory.h>

#include <string>
#include <vector>

namespace toposlam::evaluation {

/// One pose per scan of `logPath` (any log io::LaserLogReader reads: CARMEN, rawlog), in file
/// order: the scan's file stamp and the robot's cumulative odometry at that scan (odometry
/// frame). Scans before the first odometry reading are left out. Throws io::InputError like
/// the reader, and when the log has no odometry at all. `progress`: fraction of the file read
/// and scans so far.
io::Trajectory2D odometryAtScans(const std::string& logPath,
                                 const io::ProgressCallback& progress = {});

/// What a log says at its scans, read in one pass, for a caller that needs more than one of
/// them from the same log (toposlam-eval-slam given one log to several options).
struct LogScans {
    io::Trajectory2D odometry;  ///< as odometryAtScans(), but empty when the log has none
    /// One entry per scan, in file order: its file stamp (the stamps relation files use) and
    /// the laser's position on the robot as `pose` (x forward, y left, m; phi 0), as
    /// laserPositionsAtScans() (LaserFrame.h).
    io::Trajectory2D laserPositions;
};

/// Throws io::InputError like the reader.
LogScans readLogScans(const std::string& logPath, const io::ProgressCallback& progress = {});

/// `scans.odometry` (read from `logPath`); throws io::InputError naming `logPath` when the log
/// has no odometry at all.
const io::Trajectory2D& odometryOf(const LogScans& scans, const std::string& logPath);

}  // namespace toposlam::evaluation
