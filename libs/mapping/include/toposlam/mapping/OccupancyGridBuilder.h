#pragma once
// Builds the occupancy grid of a SLAM run from its scans and their estimated poses. Done
// once at the end, so the grid always agrees with the final trajectory (whatever the front
// end revised on the way). Scans are inserted as keyframes: one whenever the robot moved or
// turned enough since the previous inserted one, which keeps long logs fast without losing
// coverage.
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace toposlam::mapping {

struct OccupancyGridOptions {
    double resolution = 0.05;        ///< m per cell
    double keyframeDistance = 0.20;  ///< m travelled between inserted scans
    double keyframeAngle = 0.17453;  ///< rad turned between inserted scans (10 deg)
    /// MRPT insertion options (maxDistanceInsertion, maxOccupancyUpdateCertainty,
    /// considerInvalidRangesAsFreeSpace, ...), as in icp-slam's *_insertOpts sections.
    mrpt::maps::COccupancyGridMap2D::TInsertionOptions insertion;

    /// Reads `resolution`, `keyframeDistance` (m), `keyframeAngle_deg` and the MRPT insertion
    /// keys from `section`.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& ini, const std::string& section);
};

/// One scan and the robot pose it was taken from (map frame).
struct PosedScan {
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    mrpt::poses::CPose2D robotPose;
};

/// Grid covering every inserted scan (it grows as needed). Throws std::invalid_argument if
/// `scans` is empty.
mrpt::maps::COccupancyGridMap2D buildOccupancyGrid(const std::vector<PosedScan>& scans,
                                                   const OccupancyGridOptions& options);

}  // namespace toposlam::mapping
