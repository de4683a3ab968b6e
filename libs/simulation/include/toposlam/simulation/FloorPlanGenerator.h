#pragma once
// Random furnished buildings with exact ground truth, for benchmarking room segmentation on
// plans nobody tuned a method on (benchmarks B4-gen and B4-flats). Two kinds of building:
//
// Offices (BuildingStyle::Office, B4-gen): a rectangle with outer walls, one corridor along its
// length (sometimes with a branch or a crossing corridor to the outer wall), and the blocks
// between corridors and outer walls divided into a row of rooms along the corridor: offices,
// meeting rooms, kitchens, storage rooms, labs and open-plan areas; deep blocks sometimes put a
// second room behind the first. Every room has a door to the corridor (or to the room in front
// of it), some neighbours a door between them, halls sometimes a double door. Open-plan areas
// and labs may have partition walls that stop 2-4 m short of the opposite wall: openings wider
// than a door inside one room, which are NOT room borders.
//
// Rings (BuildingStyle::Ring, B4-rings): a corridor ring, as in many office and university
// buildings: corridors along the south and north sides joined along the west and east outer
// walls, a row of rooms between each of them and the outer wall, and two rows back to back in
// the middle block, every room filled and doored as in the offices. A loop of 80-150 m to drive
// round, lined with rooms that look alike.
//
// Flats (BuildingStyle::Flat, B4-flats; FlatFloorPlan.cpp): no corridor. The outline, sometimes
// L-shaped, is divided wall by wall (binary space partition) into a living room, bedrooms, a
// kitchen, bathrooms and box rooms; rooms open into each other: a tree of doors from the living
// room through neighbouring rooms, now and then a second door, and sometimes a kitchen open to
// the living room through a wide opening (up to 2.4 m; a border all the same: the wall line
// runs on across it). Doors sit anywhere along a wall, often a hand's width from a corner.
//
// Furniture follows how rooms are furnished, not any detector's rules (FurniturePlacer), and
// is drawn as a laser at about 0.3 m above the floor sees it: tables and most desks by their
// legs, desks with drawer pedestals or side panels, cabinets, shelves, counters, sofas, beds and
// bathtubs as solid blocks, chairs by their central column, plants and bins as discs.
//
// Ground truth: the FloorPlan's rooms (one floor box each; partition stubs inside a room are
// walls in its box) and doors. Plan frame: x east, y north, the inner faces of the outer walls'
// south-west corner at (0, 0).
#include <toposlam/simulation/FloorPlan.h>

#include <string>
#include <vector>

namespace toposlam::simulation {

enum class BuildingStyle { Office, Flat, Ring };

struct FloorPlanGeneratorOptions {
    BuildingStyle style = BuildingStyle::Office;
    double minWidth = 24, maxWidth = 44;          ///< m, office building (inner faces), east-west
    double minDepth = 15, maxDepth = 28;          ///< m, office building, north-south
    double minCorridor = 1.5, maxCorridor = 2.4;  ///< m, corridor width
    double minRingWidth = 32, maxRingWidth = 60;  ///< m, ring building, east-west (its depth,
                                                  ///< 20-34 m, follows from its rows of rooms)
    double minFlatWidth = 8, maxFlatWidth = 16;   ///< m, flat (inner faces), east-west
    double minFlatDepth = 7, maxFlatDepth = 12;   ///< m, flat, north-south
    bool furnish = true;                          ///< false: walls, rooms and doors only
};

struct GeneratedFloorPlan {
    unsigned seed = 0;
    FloorPlan plan;         ///< unfurnished when the options said so, else furnished
    FloorPlan unfurnished;  ///< the same plan without furniture
    /// Ground-truth room of each FloorRoom (index = FloorRoom id, [0] = 0): a corridor and its
    /// branches are one room; every other FloorRoom is a room of its own. 1..roomCount.
    std::vector<int> groundTruthRoom;
    int roomCount = 0;
    double outerWallThickness = 0.2, innerWallThickness = 0.1;  ///< m
    std::string summary;  ///< one line: size, rooms by kind, doors, furniture pieces
};

/// The plan of seed `seed`: the same seed and options always give the same plan (on the same
/// standard library).
GeneratedFloorPlan generateFloorPlan(unsigned seed, const FloorPlanGeneratorOptions& options = {});

}  // namespace toposlam::simulation
