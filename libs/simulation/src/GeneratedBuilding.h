#pragma once
// What every generated building has in common (FloorPlanGenerator.cpp: offices;
// FlatFloorPlan.cpp: flats): the thickness of its walls, its outer walls, its furniture, and
// the room kinds in its one-line summary.
#include <toposlam/simulation/FloorPlan.h>

#include <cstddef>
#include <map>
#include <random>
#include <string>

namespace toposlam::simulation::detail {

struct WallThicknesses {
    double outer = 0.2, inner = 0.1;  ///< m
};

/// Draws the outer wall's thickness (0.2, 0.25 or 0.3 m), then the inner walls' (0.1, 0.12 or
/// 0.15 m).
WallThicknesses drawWallThicknesses(std::mt19937& rng);

/// The four outer walls of a `width` x `depth` building (m) whose inner faces' south-west
/// corner is (0, 0).
void addOuterWalls(FloorPlan& plan, double width, double depth, double thickness);

/// Furnishes every room of `plan` by its kind (FurniturePlacer); returns the pieces placed.
std::size_t furnishRooms(FloorPlan& plan, std::mt19937& rng);

/// " 3 office 2 meeting ...": how many rooms of each kind, for a plan's summary.
std::string kindCounts(const std::map<std::string, int>& kinds);

}  // namespace toposlam::simulation::detail
