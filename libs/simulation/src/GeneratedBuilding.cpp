#include "GeneratedBuilding.h"

#include <toposlam/simulation/FurniturePlacer.h>

#include <vector>

namespace toposlam::simulation::detail {

WallThicknesses drawWallThicknesses(std::mt19937& rng) {
    WallThicknesses t;
    t.outer = std::vector<double>{0.2, 0.25, 0.3}[std::uniform_int_distribution<>(0, 2)(rng)];
    t.inner = std::vector<double>{0.1, 0.12, 0.15}[std::uniform_int_distribution<>(0, 2)(rng)];
    return t;
}

void addOuterWalls(FloorPlan& plan, double width, double depth, double thickness) {
    const double h = thickness / 2;
    plan.addWall({-h, -h}, {width + h, -h}, thickness);
    plan.addWall({-h, depth + h}, {width + h, depth + h}, thickness);
    plan.addWall({-h, -h}, {-h, depth + h}, thickness);
    plan.addWall({width + h, -h}, {width + h, depth + h}, thickness);
}

std::size_t furnishRooms(FloorPlan& plan, std::mt19937& rng) {
    FurniturePlacer placer(plan, rng);
    for (const FloorRoom& room : plan.rooms())
        placer.furnish(room);
    return placer.pieces();
}

std::string kindCounts(const std::map<std::string, int>& kinds) {
    std::string out;
    for (const auto& [kind, n] : kinds)
        out += " " + std::to_string(n) + " " + kind;
    return out;
}

}  // namespace toposlam::simulation::detail
