#pragma once
// One test case of benchmark B2: two laser scans and the true motion between them.
// All poses are ROBOT frames (each scan carries the laser's sensorPose in its robot frame).
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace toposlam::matchingbench {

struct ScanPair {
    std::string set;  ///< e.g. "sim-empty", "sim-cluttered", "intel", "mit-csail"
    mrpt::obs::CObservation2DRangeScan::Ptr reference, current;
    /// Pose of the current robot frame in the reference robot frame (m, rad).
    mrpt::poses::CPose2D truth;
    /// The same from odometry (real logs) or truth plus a known error (simulation): the
    /// guess of the "with odometry guess" runs.
    mrpt::poses::CPose2D odometry;
    double offset = 0;    ///< simulation: |translation| of the true motion (m); real: same
    double rotation = 0;  ///< |rotation| of the true motion (rad)
};
using ScanPairs = std::vector<ScanPair>;

}  // namespace toposlam::matchingbench
