#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/simulation/OfficeFloorPlan.h>
#include <toposlam/simulation/TourOrder.h>
#include <toposlam/simulation/TourPlanner.h>

#include <cmath>
#include <numeric>
#include <random>
#include <set>

#include "SimulationTestMaps.h"

using mrpt::math::TPoint2D;
using namespace toposlam::simulation;

namespace {
const FloorPlan& office() {
    static const FloorPlan plan = makeOfficeFloorPlan();
    return plan;
}
const Tour& officeTour() {
    static const auto grid = office().rasterise(0.05, 0.5);
    static const ClearanceMap map(grid);
    static const Tour tour = planTour(map, TourOptions());
    return tour;
}
}  // namespace

TEST(TourPlanner, VisitsEveryRoomOfTheOffice) {
    const Tour& tour = officeTour();
    EXPECT_TRUE(tour.unreachable.empty());
    EXPECT_EQ(tour.visitOrder.size(), tour.areas.size());
    // Visiting = being at least 0.5 m inside the room's floor (not just peeking in the door).
    for (const FloorRoom& room : office().rooms()) {
        const Box inner{room.floor.xMin + 0.5, room.floor.yMin + 0.5, room.floor.xMax - 0.5,
                        room.floor.yMax - 0.5};
        const bool visited = std::any_of(tour.poses.begin(), tour.poses.end(), [&](const auto& p) {
            return inner.contains({p.pose.x, p.pose.y});
        });
        EXPECT_TRUE(visited) << room.name;
    }
}

TEST(TourPlanner, KeepsClearOfWallsAndFurniture) {
    const Tour& tour = officeTour();
    const double robotRadius = TourOptions().robotRadius;
    for (const auto& p : tour.poses) {
        ASSERT_GE(test::distanceToSolid(office(), {p.pose.x, p.pose.y}), robotRadius)
            << "pose at t=" << p.stamp;
    }
    // Between scans too: the smoothed legs, every 5 cm.
    for (const auto& leg : tour.legs) {
        for (const TPoint2D& q : leg)
            ASSERT_GE(test::distanceToSolid(office(), q), robotRadius);
    }
}

TEST(TourPlanner, DrivesWithinTheMotionLimitsAndRecordsByDistanceAndAngle) {
    const Tour& tour = officeTour();
    const MotionOptions m;
    ASSERT_GT(tour.poses.size(), 100u);
    EXPECT_DOUBLE_EQ(tour.poses.front().stamp, m.startTime);
    // The tour closes its loop: it ends where it started.
    EXPECT_NEAR(tour.poses.back().pose.x, tour.poses.front().pose.x, 1e-9);
    EXPECT_NEAR(tour.poses.back().pose.y, tour.poses.front().pose.y, 1e-9);
    for (std::size_t i = 1; i < tour.poses.size(); ++i) {
        const auto &a = tour.poses[i - 1], &b = tour.poses[i];
        const double dt = b.stamp - a.stamp;
        const double ds = std::hypot(b.pose.x - a.pose.x, b.pose.y - a.pose.y);
        const double dyaw = std::abs(mrpt::math::wrapToPi(b.pose.phi - a.pose.phi));
        ASSERT_GT(dt, 0);
        // Stamps near 1.7e9 s are doubles exact to 2.4e-7 s: allow 1e-6 s.
        EXPECT_LE(ds, m.maxSpeed * (dt + 1e-6));
        EXPECT_LE(dyaw, m.maxTurnRate * (dt + 1e-6));
        // Recorded once the robot drove scanDistance or turned scanAngle (plus at most one
        // 5 cm path step or 1 deg turn step).
        EXPECT_LE(ds, m.scanDistance + 0.05 + 1e-9);
        EXPECT_LE(dyaw, m.scanAngle + 0.1);
    }
}

TEST(TourPlanner, RejectsMapsWithoutRoomForTheRobot) {
    mrpt::maps::COccupancyGridMap2D occupied(0.0f, 5.0f, 0.0f, 5.0f, 0.05f);
    occupied.fill(0.0f);
    EXPECT_THROW(planTour(ClearanceMap(occupied), TourOptions()), std::invalid_argument);
    // A 0.5 m wide passage: free, but the robot (0.6 m wide with margin) does not fit.
    FloorPlan narrow = test::boxRoom(5.0, 0.5);
    EXPECT_THROW(planTour(ClearanceMap(narrow.rasterise(0.05, 0.2)), TourOptions()),
                 std::invalid_argument);
    // A 1 m wide passage: the robot fits, but there is no room-sized area.
    FloorPlan corridor = test::boxRoom(5.0, 1.0);
    EXPECT_THROW(planTour(ClearanceMap(corridor.rasterise(0.05, 0.2)), TourOptions()),
                 std::invalid_argument);
}

TEST(TourOrder, TwoOptFindsTheOptimalTourOfPointsOnACircle) {
    // Shuffled points on a circle: the best closed tour goes round the circle.
    const int n = 12;
    std::vector<int> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin() + 1, perm.end(), std::mt19937(5));
    std::vector<TPoint2D> pts;
    for (int k : perm)
        pts.push_back({std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)});
    std::vector<std::vector<double>> cost(n, std::vector<double>(n));
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            cost[i][j] = std::hypot(pts[i].x - pts[j].x, pts[i].y - pts[j].y);
        }
    }
    const auto order = orderVisits(cost, true);
    ASSERT_EQ(order.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(order.front(), 0u);
    EXPECT_NEAR(tourCost(cost, order, true), n * 2 * std::sin(M_PI / n), 1e-9);
}
