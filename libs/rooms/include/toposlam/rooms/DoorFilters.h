#pragma once
// Step 5 of the virtual-door method (sec. 1.5): filters that remove virtual doors which do not
// match real doors.
//
// The paper's three filters:
//   distance:  door frames of different doors must be more than N_d cells apart; of a group of
//              closer doors one is kept;
//   adjacency: a door must touch two different regions once all doors are cut;
//   min. area: the regions on both sides of a door must be larger than N_s.
//
// Two further tests, TopoSLAM's deviations from the paper (each can be switched off; the
// paper-exact variant of RoomSegmenter turns all of them off). Both spell out what the paper
// assumes of a door (sec. 1.1: door frames lie in a wall or perpendicular to one) and are
// needed where furniture makes door-wide gaps (B4 furnished maps):
//   wall jambs:   the door lies in a wall (sec. 1.1: door frames are in a wall or
//                 perpendicular to one). Each jamb belongs to a wall: the obstacle it is on is
//                 part of the building's structure (it reaches the edge of the map, or it
//                 carries one of the wall segments of step 2) and extends at least
//                 minWallExtent from the jamb along or across the door line; and at least one
//                 jamb is the end of the wall the door is in: from it, away from the opening,
//                 the obstacle goes on along the door line for wallEndProbe and, a third of
//                 the way in, is no thicker than maxWallThickness and as thick as the
//                 building's walls are (WallThickness; or is the edge of the mapped space,
//                 free on one side only), and does not lie on the face of a wall that runs
//                 on to both sides of the door line (where a column against a wall ends).
//                 Rules out chairs, bins and plants as door frames, gaps between desks (too
//                 deep to be walls) and the cross-sections of corridors between doors (both
//                 jambs on side walls). On SLAM grids unknown space away from
//                 every occupied cell (FreeSpace::noWall: the shadow behind a table) is no
//                 jamb and no wall, and a wall seen from both sides but not inside is as thick
//                 as its faces where it goes on so for longer than furniture
//                 (hollowWallLength);
//   constriction: a door is a narrow place between two wider spaces: walking away from the door
//                 line on each side, within one door width the free space along the door line
//                 becomes wider than the door by openingMargin (rules out the cross-sections
//                 of door-wide corridors and of gaps along furniture). Judged at the waist
//                 (constrictionAtWaist): a cut is dropped when a narrower cut of the same
//                 opening does not open (an oblique cut across a corridor, whose probes reach a
//                 side door, beside the straight cut that finds the corridor no wider).
// And one more reason for the minimum-area filter to merge a region (SLAM grids): its boundary
// is mostly open to unobserved space that reaches the edge of the map (maxOpenBoundary,
// RegionBoundary.h), so it is not known to be enclosed: the pocket between two cabinets whose
// back the laser never saw.
//
// Each filter is in the source file named after it: DoorFilters.cpp (distance, adjacency),
// DoorFiltersWallJambs.cpp, DoorFiltersConstriction.cpp and DoorFiltersMinimumArea.cpp.
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/LineSegment.h>
#include <toposlam/rooms/RegionBoundary.h>
#include <toposlam/rooms/RegionPartition.h>
#include <toposlam/rooms/VirtualDoorDetector.h>
#include <toposlam/rooms/WallThickness.h>

#include <cstddef>
#include <vector>

namespace toposlam::rooms {

class DoorFilters {
  public:
    struct Options {
        /// N_d (m). The paper gives it in cells (N_d = 2 at 5 cm, fig. 5b), for SLAM maps whose
        /// walls are a few cells thick. Groups are chained (closer pairs linked), so the
        /// cross-sections found all along a doorway count as one door however thick the wall;
        /// cuts fanning out from one jamb cell at less than 30 degrees are linked too, and at
        /// less than 60 degrees where the far side of the triangle they span is wall.
        double frameDistance = 0.5;
        double minRoomArea = 2.0;  ///< N_s (m^2)
        /// Distance filter: of a group of doors closer than N_d, keep the narrowest (the
        /// waist of the opening; ties: the one nearest the group's middle). Off: the paper's
        /// greedy reading, keep each door that is more than N_d from every door kept before it.
        bool keepNarrowestOfGroup = true;
        /// Minimum-area filter: merge the smallest too-small region first, through its widest
        /// door (of two cuts through one doorway the waist stays; ties: to its smallest
        /// neighbour), and re-evaluate. Off: the paper's single pass, remove every door with a
        /// too-small region on either side.
        bool mergeSmallestFirst = true;
        bool requireWallJambs = true;  ///< the wall-jamb test (deviation, see above)
        double minWallExtent = 0.3;    ///< m
        /// Part of the wall-jamb test: at least one jamb must end the wall the door is in.
        bool requireWallEnd = true;
        /// Stricter (WideOpeningDetector's openings): both jambs end the wall, neither lies
        /// in the middle of a wall running across the door line, and the two do not lie on
        /// walls that go on to the same side of it (a corridor's two side walls).
        bool requireBothWallEnds = false;
        /// Part of the wall-end test: no door has both jambs on walls that go on, farther than
        /// maxWallThickness plus two cells, to the same side of the door line: that cut runs
        /// across a corridor between its side walls (beside a side door, whose wall end passes
        /// the test). Walls across the door line are found by walking the obstacle from the jamb
        /// and from the wall segments passing within 0.25 m of it (a cut at an angle to the grid
        /// ends anywhere on a wall's staircase).
        bool rejectCorridorCuts = true;
        /// Part of the wall-end test: the jamb that ends the door's wall does not lie on the
        /// face of a wall that runs across the door line to both sides, farther than
        /// wallEndProbe (a wall seen edge-on, a T-junction of walls): from such a jamb the cut
        /// runs along the face's normal into the room or corridor the face bounds (to a pillar,
        /// a cabinet on the far wall), not across a doorway.
        bool wallEndNotOnAFace = true;
        /// m: the thickest inner wall (B4's drawn walls: 0.55 m in Freiburg52, 0.65 m in office_i).
        double maxWallThickness = 0.65;
        /// m, part of the wall-end test on SLAM grids: a wall the laser saw from both sides but
        /// not inside (two faces with unknown cells between them, farther apart than twice the
        /// binariser's wallHoleReach: a thick or double wall, a duct beside a corridor) is as
        /// thick as its faces where it goes on so for this long from the jamb, along the door
        /// line: longer than furniture, whose unseen inside looks the same from its front
        /// (RoomSegmenter's maxFurnitureSize). 0 = off: its unseen inside counts, and such a
        /// wall is thicker than maxWallThickness.
        double hollowWallLength = 2.5;
        /// m, part of the wall-jamb test: a piece of wall between two openings, too short to
        /// carry a wall segment (a pier between two doorways), belongs to the building when it
        /// lies in the line of an inner wall (a segment of at least 2 m), no thicker than that
        /// wall and longer than thick, with openings of at most this width to the wall on
        /// either side; and it ends its wall at both ends, however short (down to
        /// minWallExtent). 0 = off: such a piece is free-standing furniture.
        double maxPierGap = 3.0;
        /// m: how far from a wall-end jamb, along the door line, the wall must go on and is
        /// measured for its thickness (and the reach of the wide openings' framing test).
        double wallEndProbe = 0.55;
        /// m: a wall end with free space on one side only is the edge of the mapped space when
        /// nothing is free within this on the other side; furniture against an inner wall has
        /// the next room behind it (a bed of up to 2.1 m with its head to a wall up to 0.3 m
        /// thick). At most twice maxWallThickness: the check of that reach alone (off).
        double edgeDepth = 2.4;
        /// Part of the wall-end test: the wall end must also be as thick as the building's
        /// walls are, measured on the map (WallThickness.h), so that a cabinet, a fridge or a
        /// shelf standing against a wall is no wall end.
        bool wallThicknessFromMap = true;
        bool requireConstriction = true;  ///< the constriction test (deviation, see above)
        double openingMargin = 0.3;       ///< m
        /// Part of the constriction test: a door that opens on both sides is still dropped when
        /// a narrower cut through the same opening (jambs within frameDistance) does not open:
        /// the opening is judged at its waist, whatever the angle of the cut to the grid.
        bool constrictionAtWaist = true;
        /// Minimum-area filter (deviation, SLAM grids): a region whose boundary (door cuts
        /// excepted) is more than this fraction open to the unobserved outside
        /// (RegionBoundary.h) is not known to be a room and is merged like a too-small one;
        /// 1 = off.
        double maxOpenBoundary = 0.4;
    };

    DoorFilters() = default;
    explicit DoorFilters(const Options& options) : options_(options) {}

    /// The wall-jamb test (a no-op when switched off); `walls`: the merged wall segments of
    /// step 2 (pixels); `thickness`: the map's wall thicknesses (nullptr: any up to
    /// maxWallThickness).
    std::vector<VirtualDoor> wallJambs(const FreeSpace& space, std::vector<VirtualDoor> doors,
                                       const std::vector<LineSegment>& walls,
                                       const WallThickness* thickness = nullptr) const;
    /// The constriction test; `probeDistance` (how far from the door line to look, m) is the
    /// door width (a no-op when off).
    std::vector<VirtualDoor> constriction(const FreeSpace& space, std::vector<VirtualDoor> doors,
                                          double probeDistance) const;
    /// The distance filter (`space`: where the cuts fan out from one jamb, whether the far
    /// side of the triangle they span is wall).
    std::vector<VirtualDoor> distance(const FreeSpace& space, std::vector<VirtualDoor> doors) const;
    /// The adjacency filter: indices of the doors of `partition` that touch two regions.
    static std::vector<std::size_t> adjacency(const RegionPartition& partition);

    /// Result of the minimum-area filter.
    struct Rooms {
        /// Partition label -> room id (1..roomCount); [0] = 0.
        std::vector<int> roomOfRegion;
        int roomCount = 0;
        /// The surviving doors (indices into the partition's doors) and the two rooms each joins.
        struct Link {
            std::size_t door;
            int roomA, roomB;
        };
        std::vector<Link> doors;
    };
    /// The minimum-area filter over the doors `candidates` (indices into `doors`, the doors
    /// `partition` was cut with); regions are merged through removed doors. `cellArea` in m^2.
    /// Doors whose two sides end up in one room are dropped too (they no longer separate
    /// anything). `boundary` (measured on `partition`; nullptr: none) adds the regions whose
    /// boundary is mostly open to the unobserved outside (maxOpenBoundary) to the too-small
    /// ones.
    Rooms minimumArea(const RegionPartition& partition, const std::vector<VirtualDoor>& doors,
                      const std::vector<std::size_t>& candidates, double cellArea,
                      const RegionBoundary* boundary = nullptr) const;

    const Options& options() const { return options_; }

  private:
    Options options_;
};

}  // namespace toposlam::rooms
