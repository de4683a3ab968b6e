#pragma once
// Builds the occupancy grid of a SLAM run from its scans and their estimated poses. Done
// once at the end, so the grid always agrees with the final trajectory (whatever the front
// end revised on the way). Scans are inserted as keyframes: one whenever the robot moved or
// turned enough since the previous inserted one, which keeps long logs fast without losing
// coverage.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/Options.h>

#include <string>
#include <vector>

namespace toposlam::mapping {

/// Section [OccupancyGrid] of config_ini/toposlam-slam.ini.
struct OccupancyGridOptions : public config::Options {
    double resolution = 0.05;        ///< m per cell
    double keyframeDistance = 0.20;  ///< m travelled between inserted scans
    double keyframeAngle = 0.17453;  ///< rad turned between inserted scans (10 deg)
    /// Turn the map so its dominant walls run along the axes (ManhattanAlignment.h) when at
    /// least this fraction of local wall pieces agree on the direction.
    bool alignWithWalls = true;
    double minWallDirectionStrength = 0.2;
    /// MRPT insertion options; declared: max_distance_insertion,
    /// max_occupancy_update_certainty, max_freeness_update_certainty,
    /// max_freeness_invalid_ranges, consider_invalid_ranges_as_free_space, decimation (the
    /// others, for 3D or image features, keep MRPT's defaults).
    mrpt::maps::COccupancyGridMap2D::TInsertionOptions insertion;

    void declare(config::OptionsSchema& s) override;
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
