#pragma once
// MRPT icp-slam's per-step pose file, log_estimated_path.txt, turned into a trajectory with
// time stamps, so that the stock icp-slam is scored like any TopoSLAM run.
//
// icp-slam (MRPT 2.5.8, libs/apps/src/ICP_SLAM_App.cpp) writes one line "step x y yaw" for every
// rawlog entry it processes and no time stamp. What an entry is comes from
// CRawlog::getActionObservationPairOrObservation:
//  - observation-only rawlogs: every CObservation object is an entry, odometry included;
//  - actions/sensory-frames rawlogs: every (CActionCollection, CSensoryFrame) pair is one entry;
//  - any other object is skipped without a line.
// The pose on an entry's line is the estimate after that entry was processed, so the line of a
// scan entry is the robot pose at that scan. The scan entries of the rawlog icp-slam ran on give
// those lines their stamps; the other lines (odometry) are dropped. Poses are in icp-slam's map
// frame (its first pose is the origin), which the relation metric does not care about.
#include <toposlam/io/Trajectory.h>

#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct IcpSlamScanStep {
    std::size_t step = 0;  ///< 0-based line of log_estimated_path.txt
    double stamp = 0;      ///< the scan's MRPT timestamp as Unix seconds (mrpt::Clock::toDouble)
};

struct IcpSlamSteps {
    std::size_t totalSteps = 0;          ///< lines icp-slam writes for this rawlog
    std::vector<IcpSlamScanStep> scans;  ///< the steps holding a CObservation2DRangeScan
};

/// Walks `rawlogPath` (plain or gz, either format) the way icp-slam does. Throws io::InputError
/// for a missing or unreadable file, or an object of a class MRPT does not know (icp-slam would
/// silently stop there, so its path would not match the whole rawlog anyway).
IcpSlamSteps icpSlamStepsOf(const std::string& rawlogPath);

/// Reads icp-slam's `log_estimated_path.txt` written for `rawlogPath` and returns one pose per
/// scan. The stamps are the scans' rawlog stamps, or `scanStamps` (one per scan, in rawlog
/// order) when given: relation files use the stamps as printed in the original CARMEN log,
/// which a rawlog may not keep exactly (e.g. intel's backwards stamps). Throws io::InputError
/// when the path file is missing or malformed (not "step x y yaw" with finite numbers and steps
/// 0, 1, 2, ...), when its line count differs from the rawlog's step count (a path of another
/// rawlog, or a truncated run), or when `scanStamps` has the wrong size.
io::Trajectory2D loadIcpSlamPath(const std::string& pathFile, const std::string& rawlogPath,
                                 const std::vector<double>* scanStamps = nullptr);

}  // namespace toposlam::evaluation
