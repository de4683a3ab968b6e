#include <gtest/gtest.h>
#include <toposlam/simulation/MovingObstacles.h>
#include <toposlam/simulation/OfficeFloorPlan.h>

#include "SimulationTestMaps.h"

using mrpt::math::TPoint2D;
using namespace toposlam::simulation;

TEST(MovingObstacles, PeopleWalkThroughTheOfficeAndNeverThroughWalls) {
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(0.05, 0.5);
    const ClearanceMap map(grid);
    PeopleOptions options;
    options.count = 6;
    const TPoint2D robot(12, 6.5);
    MovingObstacles people(map, options, robot, 42);
    ASSERT_EQ(people.discs().size(), options.count);

    std::vector<double> walked(options.count, 0.0);
    std::vector<TPoint2D> previous;
    for (const Disc& d : people.discs())
        previous.push_back(d.centre);
    const double dt = 0.1;
    for (int step = 0; step < 3000; ++step) {  // 5 minutes
        people.advance(dt, robot);
        for (std::size_t i = 0; i < options.count; ++i) {
            const Disc& d = people.discs()[i];
            // The whole disc stays in free space (exact distance to the vector plan).
            ASSERT_GE(test::distanceToSolid(plan, d.centre), options.radius)
                << "person " << i << " at step " << step;
            ASSERT_TRUE(plan.extent().contains(d.centre)) << "inside the building";
            const double moved = std::hypot(d.centre.x - previous[i].x, d.centre.y - previous[i].y);
            EXPECT_LE(moved, options.maxSpeed * dt + 1e-9) << "walking speed";
            walked[i] += moved;
            previous[i] = d.centre;
        }
    }
    for (std::size_t i = 0; i < options.count; ++i) {
        // Walking at >= 0.8 m/s with pauses <= 3 s per trip: far more than 30 m in 5 min.
        EXPECT_GT(walked[i], 30.0) << "person " << i << " hardly moved";
    }
}

TEST(MovingObstacles, PeopleKeepOutOfTheRobotsWay) {
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(0.05, 0.5);
    const ClearanceMap map(grid);
    PeopleOptions options;
    options.count = 8;
    const TPoint2D robot(12, 6.5);  // standing in the corridor
    MovingObstacles people(map, options, robot, 7);
    for (int step = 0; step < 3000; ++step) {
        people.advance(0.1, robot);
        for (const Disc& d : people.discs()) {
            ASSERT_GE(std::hypot(d.centre.x - robot.x, d.centre.y - robot.y),
                      options.robotKeepOut - 1e-9);
        }
    }
}
