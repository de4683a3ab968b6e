#include <mrpt/poses/CPose3D.h>
#include <toposlam/mapping/OccupancyGridBuilder.h>

#include <cmath>
#include <stdexcept>

namespace toposlam::mapping {

void OccupancyGridOptions::declare(config::OptionsSchema& s) {
    s.real("resolution", resolution, "m", "cell size of the output grid").within(0.001, 10);
    s.real("keyframe_distance", keyframeDistance, "m",
           "scans are inserted every keyframe_distance travelled ...")
        .atLeast(0);
    s.angle("keyframe_angle", keyframeAngle, "... or keyframe_angle_deg turned").atLeast(0);
    s.flag("align_with_walls", alignWithWalls,
           "turn the map so the dominant walls run along the x and y axes");
    s.real("min_wall_direction_strength", minWallDirectionStrength, "",
           "... when at least this fraction of local wall pieces agree on the direction")
        .within(0, 1);
    s.real("max_distance_insertion", insertion.maxDistanceInsertion, "m",
           "readings beyond this range are not inserted")
        .above(0);
    s.real("max_occupancy_update_certainty", insertion.maxOccupancyUpdateCertainty, "",
           "Bayesian update of an occupied cell per reading (MRPT)")
        .within(0.5, 1);
    s.real("max_freeness_update_certainty", insertion.maxFreenessUpdateCertainty, "",
           "... of a free cell (0: as max_occupancy_update_certainty)")
        .within(0, 1);
    s.real("max_freeness_invalid_ranges", insertion.maxFreenessInvalidRanges, "",
           "... of a free cell along a reading without return (0: the same)")
        .within(0, 1);
    s.flag("consider_invalid_ranges_as_free_space", insertion.considerInvalidRangesAsFreeSpace,
           "readings without a return are evidence of free space (not in CARMEN logs, which "
           "mark no-returns with the maximum range)");
    s.integer("decimation", insertion.decimation, "", "insert every decimation-th reading")
        .within(1, 1000);
}

mrpt::maps::COccupancyGridMap2D buildOccupancyGrid(const std::vector<PosedScan>& scans,
                                                   const OccupancyGridOptions& options) {
    if (scans.empty())
        throw std::invalid_argument("buildOccupancyGrid: no scans");
    const auto& first = scans.front().robotPose;
    const auto res = static_cast<float>(options.resolution);
    // Start small around the first pose; insertObservation() grows the grid as scans need.
    mrpt::maps::COccupancyGridMap2D grid(
        static_cast<float>(first.x() - 10), static_cast<float>(first.x() + 10),
        static_cast<float>(first.y() - 10), static_cast<float>(first.y() + 10), res);
    grid.insertionOptions = options.insertion;

    const mrpt::poses::CPose2D* lastInserted = nullptr;
    for (const PosedScan& s : scans) {
        if (lastInserted) {
            const mrpt::poses::CPose2D delta = s.robotPose - *lastInserted;
            if (delta.norm() < options.keyframeDistance &&
                std::abs(delta.phi()) < options.keyframeAngle) {
                continue;
            }
        }
        grid.insertObservation(*s.scan, mrpt::poses::CPose3D(s.robotPose));
        lastInserted = &s.robotPose;
    }
    return grid;
}

}  // namespace toposlam::mapping
