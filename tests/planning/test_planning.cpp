// Room-to-room planning on a hand-drawn floor with exact geometry: two rooms either side of a
// corridor, each joined to it by one door, and a closet with no door.
#include <gtest/gtest.h>
#include <toposlam/planning/RoomRoute.h>
#include <toposlam/planning/RoomToRoomPlanner.h>
#include <toposlam/planning/ShortestGridPath.h>

#include <ompl/util/RandomNumbers.h>
#include <cmath>
#include <fstream>

#include "TestSupport.h"

using mrpt::math::TPoint2D;
using namespace toposlam;

namespace {

constexpr double kRes = 0.05;
// OMPL's seed must be set before its first sampler exists: reproducible plans in every test.
const bool kSeeded = (ompl::RNG::setSeed(1), true);

// 12 m x 8 m. Rooms (world, m): west [0,5]x[0,5] (id 1), east [7,12]x[0,5] (id 2), corridor
// [0,12]x[5.1,8] (id 3), closet [5.1,6.9]x[0,3] (id 4, walled in). Walls are one cell thick;
// doors are 1.0 m gaps in the wall y = 5.05 at x in [2,3] (west) and [9,10] (east).
struct Floor {
    mrpt::maps::COccupancyGridMap2D grid{0.0f, 12.0f, 0.0f, 8.0f, static_cast<float>(kRes)};
    rooms::TopologicalMap map;
};

bool isWall(double x, double y) {
    const bool border = x < kRes || x > 12 - kRes || y < kRes || y > 8 - kRes;
    const bool corridorWall =
        std::abs(y - 5.05) < kRes / 2 + 1e-9 && !(x > 2 && x < 3) && !(x > 9 && x < 10);
    const bool closet =
        (std::abs(x - 5.05) < kRes / 2 + 1e-9 || std::abs(x - 6.95) < kRes / 2 + 1e-9) && y < 5.05;
    const bool closetTop = std::abs(y - 3.05) < kRes / 2 + 1e-9 && x > 5 && x < 7;
    return border || corridorWall || closet || closetTop;
}

int roomOf(double x, double y) {
    if (y > 5.1)
        return 3;
    if (x < 5.0)
        return 1;
    if (x > 7.0)
        return 2;
    return y < 3.0 ? 4 : 0;  // the strip above the closet belongs to no room
}

Floor makeFloor() {
    Floor f;
    const rooms::GridImageFrame frame{kRes, 0.0, 0.0, static_cast<int>(f.grid.getSizeX()),
                                      static_cast<int>(f.grid.getSizeY())};
    cv::Mat labels(frame.rows, frame.cols, CV_32S, cv::Scalar(0));
    for (int cy = 0; cy < frame.rows; ++cy) {
        for (int cx = 0; cx < frame.cols; ++cx) {
            const double x = f.grid.idx2x(cx), y = f.grid.idx2y(cy);
            const bool wall = isWall(x, y);
            f.grid.setCell(cx, cy, wall ? 0.0f : 1.0f);
            if (!wall)
                labels.at<int>(frame.rows - 1 - cy, cx) = roomOf(x, y);
        }
    }
    f.map = rooms::TopologicalMap::fromLabels(frame, labels);
    rooms::Door west{1, {2.0, 5.05}, {3.0, 5.05}, 1.0, 1, 3};
    rooms::Door east{2, {9.0, 5.05}, {10.0, 5.05}, 1.0, 2, 3};
    f.map.doors = {west, east};
    return f;
}

bool pathIsCollisionFree(const planning::TraversabilityGrid& grid,
                         const std::vector<TPoint2D>& points) {
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double len = std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
        const int steps = std::max(1, static_cast<int>(std::ceil(len / (kRes / 4))));
        for (int k = 0; k <= steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            if (!grid.isTraversable(points[i - 1].x + t * (points[i].x - points[i - 1].x),
                                    points[i - 1].y + t * (points[i].y - points[i - 1].y))) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

TEST(TraversabilityGrid, ClearanceFollowsTheWalls) {
    const Floor f = makeFloor();
    const planning::TraversabilityGrid grid(f.grid, 0.25);
    // Cell centres: the west wall occupies x in [0, 0.05]; a cell centred at x = 0.325 is
    // 0.275 m from it, one at 0.275 only 0.225 m.
    EXPECT_TRUE(grid.isTraversable(0.325, 2.5));
    EXPECT_FALSE(grid.isTraversable(0.275, 2.5));
    EXPECT_NEAR(grid.clearance(2.5, 2.5), 2.45, kRes) << "room centre, 2.5 m from the walls";
    EXPECT_TRUE(grid.isTraversable(2.5, 5.05)) << "a 1 m door passes a 0.5 m robot";
    const planning::TraversabilityGrid wide(f.grid, 0.55);
    EXPECT_FALSE(wide.isTraversable(2.5, 5.05)) << "but not a 1.1 m one";
}

TEST(RoomRoute, CrossesTheRightDoors) {
    const Floor f = makeFloor();
    const auto route = planning::findRoomRoute(f.map, 1, {2.5, 2.5}, 2, {9.5, 2.5});
    ASSERT_TRUE(route);
    EXPECT_EQ(route->rooms, (std::vector<int>{1, 3, 2}));
    EXPECT_EQ(route->doors, (std::vector<int>{1, 2}));
    ASSERT_EQ(route->waypoints.size(), 4u);
    EXPECT_NEAR(route->estimatedLength, 2.55 + 7.0 + 2.55, 1e-9);
    const auto same = planning::findRoomRoute(f.map, 1, {1, 1}, 1, {4, 4});
    ASSERT_TRUE(same);
    EXPECT_TRUE(same->doors.empty());
    EXPECT_FALSE(planning::findRoomRoute(f.map, 1, {2.5, 2.5}, 4, {6, 1.5}))
        << "the closet has no door";
}

TEST(ShortestGridPath, ShortestPathLengthIsNearTheEuclideanBound) {
    const Floor f = makeFloor();
    const planning::TraversabilityGrid grid(f.grid, 0.25);
    planning::ShortestGridPath astar(grid);
    const auto straight = astar.plan({1.0, 1.0}, {4.0, 1.0});
    ASSERT_TRUE(straight);
    EXPECT_NEAR(straight->length, 3.0, 1e-5);  // costs add up in float
    const auto across = astar.plan({2.5, 2.5}, {9.5, 2.5});
    ASSERT_TRUE(across);
    // Through both doors: at least the straight-line route via the door middles' lower bound.
    EXPECT_GT(across->length, 2 * std::hypot(2.55, 0.0) + 7.0 - 1e-6);
    EXPECT_TRUE(pathIsCollisionFree(grid, across->points));
    EXPECT_FALSE(astar.plan({2.5, 2.5}, {6.0, 1.5})) << "closet unreachable";
}

TEST(RoomToRoomPlanner, PlansThroughDoorsCollisionFree) {
    const Floor f = makeFloor();
    const planning::TraversabilityGrid grid(f.grid, 0.25);
    planning::ShortestGridPath astar(grid);
    planning::RoomToRoomPlanner planner(f.map, grid);
    const planning::RoomPath path = planner.plan(1, 2);
    ASSERT_TRUE(path.solved) << path.failure;
    EXPECT_EQ(path.route.doors, (std::vector<int>{1, 2}));
    EXPECT_EQ(f.map.roomAt(path.points.front().x, path.points.front().y), 1);
    EXPECT_EQ(f.map.roomAt(path.points.back().x, path.points.back().y), 2);
    EXPECT_TRUE(pathIsCollisionFree(grid, path.points));
    const auto reference = astar.plan(path.points.front(), path.points.back());
    ASSERT_TRUE(reference);
    // A* on an 8-connected grid overestimates a shortest path by up to 8 %; a shortened
    // sampling-based path should be within 10 % above it.
    EXPECT_GT(path.length, reference->length / 1.09);
    EXPECT_LT(path.length, reference->length * 1.10);
    EXPECT_NEAR(path.length, planning::polylineLength(path.points), 1e-9);
}

TEST(RoomToRoomPlanner, ReportsWhyThereIsNoPath) {
    const Floor f = makeFloor();
    const planning::TraversabilityGrid grid(f.grid, 0.25);
    planning::RoomToRoomPlanner planner(f.map, grid);
    const auto closet = planner.plan(1, 4);
    EXPECT_FALSE(closet.solved);
    EXPECT_NE(closet.failure.find("not connected"), std::string::npos) << closet.failure;

    const planning::TraversabilityGrid wide(f.grid, 0.55);
    planning::RoomToRoomPlanner widePlanner(f.map, wide);
    const auto blocked = widePlanner.plan(1, 2);
    EXPECT_FALSE(blocked.solved);
    EXPECT_NE(blocked.failure.find("too narrow"), std::string::npos) << blocked.failure;
    EXPECT_THROW(planner.plan(1, 99), std::invalid_argument);
}

TEST(RoomToRoomPlanner, SavesThePath) {
    const Floor f = makeFloor();
    const planning::TraversabilityGrid grid(f.grid, 0.25);
    planning::RoomToRoomPlanner planner(f.map, grid);
    const auto path = planner.plan(1, 2);
    ASSERT_TRUE(path.solved);
    test::TempDir dir;
    planning::savePath(path, dir.file("path.txt"));
    std::ifstream in(dir.file("path.txt"));
    std::string line;
    std::size_t points = 0;
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] != '#')
            ++points;
    }
    EXPECT_EQ(points, path.points.size());
    planning::RoomPath unsolved;
    EXPECT_THROW(planning::savePath(unsolved, dir.file("bad.txt")), std::invalid_argument);
}
