#include <gtest/gtest.h>
#include <toposlam/simulation/GridWorld.h>
#include <toposlam/simulation/OfficeFloorPlan.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "SimulationTestMaps.h"

using mrpt::math::TPoint2D;
using namespace toposlam::simulation;

namespace {
// Floats in COccupancyGridMap2D (origin, resolution) put cell edges up to ~1e-6 m off the
// exact multiples of 0.05 m over 25 m.
constexpr double kFloatTolerance = 1e-5;
}  // namespace

TEST(GridWorld, RaysInsideABoxRoomHitTheWallFacesExactly) {
    // Floor [0,4] x [0,3]; the wall faces are cell edges, so the grid is exact.
    const FloorPlan plan = test::boxRoom(4.0, 3.0);
    const auto grid = plan.rasterise(0.05, 0.2);
    const GridWorld world(grid);
    const TPoint2D o(1.23, 0.71);
    for (int k = 0; k < 360; ++k) {
        const double a = (k + 0.37) * M_PI / 180;
        const double c = std::cos(a), s = std::sin(a);
        const double tx = c > 0 ? (4.0 - o.x) / c : -o.x / c;  // analytic: first face crossed
        const double ty = s > 0 ? (3.0 - o.y) / s : -o.y / s;
        EXPECT_NEAR(world.castRay(o, a, 50), std::min(tx, ty), kFloatTolerance) << "angle " << a;
    }
}

TEST(GridWorld, MaxRangeOriginInWallAndDiscs) {
    const auto grid = test::boxRoom(4.0, 3.0).rasterise(0.05, 0.2);
    GridWorld world(grid);
    EXPECT_TRUE(std::isinf(world.castRay({1, 1}, 0.0, 2.5))) << "the wall is 3 m away";
    EXPECT_NEAR(world.castRay({1, 1}, 0.0, 3.5), 3.0, kFloatTolerance);
    EXPECT_EQ(world.castRay({-0.05, 1}, 0.0, 10), 0.0) << "sensor inside the wall";
    world.discs().push_back({{2.0, 1.0}, 0.25});
    EXPECT_NEAR(world.castRay({1, 1}, 0.0, 10), 0.75, 1e-12) << "a person occludes the wall";
    EXPECT_NEAR(world.castRay({1, 1}, M_PI, 10), 1.0, kFloatTolerance) << "behind: the wall";
}

TEST(GridWorld, UnknownCellsAndTheMapEdge) {
    mrpt::maps::COccupancyGridMap2D grid(0.0f, 2.0f, 0.0f, 2.0f, 0.05f);
    grid.fill(1.0f);  // all free, no walls: rays leave the map
    for (int cy = 0; cy < 40; ++cy)
        grid.setCell(30, cy, 0.5f);  // unknown column x in [1.5,1.55)
    GridWorldOptions stopping;
    stopping.unknownIsObstacle = true;
    EXPECT_NEAR(GridWorld(grid, stopping).castRay({0.5, 1}, 0.0, 10), 1.0, kFloatTolerance);
    EXPECT_NEAR(GridWorld(grid, stopping).castRay({0.5, 1}, M_PI, 10), 0.5, kFloatTolerance)
        << "the map's edge counts as unknown";
    GridWorldOptions seeThrough;
    seeThrough.unknownIsObstacle = false;
    EXPECT_TRUE(std::isinf(GridWorld(grid, seeThrough).castRay({0.5, 1}, 0.0, 10)));
    // From outside the map, with unknown = free, the ray enters and hits an occupied cell.
    grid.setCell(10, 20, 0.0f);  // x in [0.5, 0.55), y in [1.0, 1.05)
    EXPECT_NEAR(GridWorld(grid, seeThrough).castRay({-1, 1.02}, 0.0, 10), 1.5, kFloatTolerance);
}

TEST(GridWorld, MatchesTheExactVectorWorldOfTheOffice) {
    // Every wall and box of the office lies on cell edges, so the rasterised office must give
    // the same ranges as the vector office, except near the round kitchen table (the only
    // curved solid, which the grid approximates within one cell).
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(0.05, 0.5);
    const GridWorld gridWorld(grid);
    const PolygonWorld vectorWorld = plan.toPolygonWorld();
    const Disc table = plan.furnitureDiscs().at(0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(0, 24), uy(0, 13), ua(-M_PI, M_PI);
    int compared = 0;
    while (compared < 3000) {
        const double y = uy(rng), x = ux(rng);  // one draw per statement
        const TPoint2D o(x, y);
        if (test::distanceToSolid(plan, o) < 0.05 || plan.roomAt(o) == 0)
            continue;
        const double a = ua(rng);
        const double exact = vectorWorld.castRay(o, a, 30);
        ASSERT_TRUE(std::isfinite(exact)) << "the office is closed";
        // Skip rays that pass within a cell diagonal of the table (closest approach).
        const double along =
            std::clamp((table.centre.x - o.x) * std::cos(a) + (table.centre.y - o.y) * std::sin(a),
                       0.0, exact);
        const TPoint2D closest(o.x + along * std::cos(a), o.y + along * std::sin(a));
        if (std::hypot(closest.x - table.centre.x, closest.y - table.centre.y) <
            table.radius + 0.08) {
            continue;
        }
        ASSERT_NEAR(gridWorld.castRay(o, a, 30), exact, kFloatTolerance)
            << "from (" << o.x << ", " << o.y << ") at " << a;
        ++compared;
    }
}
