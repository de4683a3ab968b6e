#pragma once
// Most buildings are "Manhattan worlds": their walls run along two perpendicular directions.
// A SLAM map starts in the frame of the robot's first pose, so its walls are at whatever angle
// the robot happened to face; this finds the walls' direction so the map can be turned to put
// them along the grid axes (straight walls without staircase aliasing, images that read like
// floor plans, and the main directions room segmentation expects).
#include <toposlam/mapping/OccupancyGridBuilder.h>

#include <optional>
#include <vector>

namespace toposlam::mapping {

struct WallDirection {
    double angle = 0;     ///< rad in (-pi/4, pi/4]: walls run at angle and angle + pi/2
    double strength = 0;  ///< in [0, 1]: 1 = every wall piece exactly on one of the two
};

/// The dominant wall direction (modulo 90 deg) of the scans, in the map frame of their poses:
/// the direction of every short run of consecutive scan points (local wall pieces) votes with
/// weight 1 as a unit vector at four times its angle, whose resultant's angle / 4 is the
/// direction; a second pass keeps only pieces within 10 deg of it (furniture and clutter at
/// other angles do not pull it). nullopt when the scans hold no wall pieces.
std::optional<WallDirection> estimateWallDirection(const std::vector<PosedScan>& scans);

}  // namespace toposlam::mapping
