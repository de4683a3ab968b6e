#pragma once
// What a tour leaves unseen, and where the robot must stop to see it. A tour that visits the
// room-sized areas (RoomSizedAreas) skips rooms too small to survive the erosion by half a door
// width (closets, a vestibule's side rooms) and the part of a room hidden behind furniture: a
// person driving the robot would look into them. So: mark the free cells in line of sight of
// the tour's path (within a view range, in every direction: the simulated laser sees 270°),
// take every connected area of free cells left unseen that is large enough to matter, and for
// each choose stops until what it still hides no longer matters: inside it where the robot fits
// (the middle of its widest room first: a whole wing the tour missed gets one per room), else
// the reachable place nearest to it along free space (a closet's doorway).
#include <mrpt/math/TPoint2D.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/ClearanceMap.h>

#include <cstdint>
#include <vector>

namespace toposlam::simulation {

struct TourCoverageOptions {
    /// Look into every unseen area (off: the tour visits the room-sized areas only). Off by
    /// default: the bundled office data set (share/office) was made without it.
    bool lookIntoUnseen = false;
    /// m; a free cell counts as seen from a path point within this straight-line distance
    /// (less than the laser's range: far cells are seen at grazing angles, if at all).
    double viewRange = 5.0;
    /// m^2; unseen areas smaller than this (pockets behind a chair) are left unseen.
    double minUnseenAreaM2 = 1.0;
};

/// 1 for every cell in line of sight (through free cells, at most `range` m) of one of the
/// `viewpoints` (world frame, m), the first non-free cell of each sight line included; indexed
/// by GridGeometry::index. Viewpoints outside the map or not in a free cell see nothing.
std::vector<std::uint8_t> cellsInView(const ClearanceMap& map,
                                      const std::vector<mrpt::math::TPoint2D>& viewpoints,
                                      double range);
/// The same from the positions of a driven trajectory (what its scans had in view).
std::vector<std::uint8_t> cellsInView(const ClearanceMap& map, const io::Trajectory2D& poses,
                                      double range);

struct UnseenArea {
    double areaM2 = 0;              ///< free cells in it
    mrpt::math::TPoint2D centroid;  ///< world frame, m
    /// Where to stop to see it (world frame, m): one for a closet (its doorway), one per room
    /// for a wing the tour did not enter; none when no reachable place is within view range.
    std::vector<mrpt::math::TPoint2D> viewpoints;
};

/// The 8-connected areas of free cells not in `seen` of at least options.minUnseenAreaM2, each
/// with the stops from where the robot sees it, chosen greedily until what it still hides is
/// smaller than options.minUnseenAreaM2: the `reachable` cell (indexed like `seen`: the robot can
/// get there from the tour) of the hidden part farthest from obstacles, or, when it has none,
/// the reachable place nearest to it (walking through free cells, at most options.viewRange).
/// A stop sees what is in line of sight within options.viewRange. Largest first. With
/// `skipOpenToMapEdge`, areas that reach the map's edge (the free background around a drawn
/// building, see Tour::outside) are left out.
std::vector<UnseenArea> findUnseenAreas(const ClearanceMap& map,
                                        const std::vector<std::uint8_t>& seen,
                                        const std::vector<std::uint8_t>& reachable,
                                        const TourCoverageOptions& options,
                                        bool skipOpenToMapEdge = false);

}  // namespace toposlam::simulation
