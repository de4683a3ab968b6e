#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/simulation/OfficeFloorPlan.h>
#include <toposlam/simulation/SimulatorConfig.h>
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
const ClearanceMap& officeMap() {
    static const auto grid = office().rasterise(0.05, 0.5);
    static const ClearanceMap map(grid);
    return map;
}
const Tour& officeTour() {
    static const Tour tour = planTour(officeMap(), TourOptions());
    return tour;
}
/// The same, with stops to look into what the room-sized tour leaves unseen.
const Tour& officeTourLookingIntoUnseen() {
    static const Tour tour = [] {
        TourOptions o;
        o.coverage.lookIntoUnseen = true;
        return planTour(officeMap(), o);
    }();
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
    for (const Tour* tour : {&officeTour(), &officeTourLookingIntoUnseen()}) {
        const double robotRadius = TourOptions().robotRadius;
        for (const auto& p : tour->poses) {
            ASSERT_GE(test::distanceToSolid(office(), {p.pose.x, p.pose.y}), robotRadius)
                << "pose at t=" << p.stamp;
        }
        // Between scans too: the smoothed legs, every 5 cm.
        for (const auto& leg : tour->legs) {
            for (const TPoint2D& q : leg)
                ASSERT_GE(test::distanceToSolid(office(), q), robotRadius);
        }
    }
}

TEST(TourPlanner, LookingIntoUnseenAreasLeavesLessUnseen) {
    // The office's tour leaves corners behind cabinets and tables unseen; the stops added for
    // them leave fewer unseen areas, none larger than before.
    const Tour& looking = officeTourLookingIntoUnseen();
    ASSERT_FALSE(looking.unseen.empty());
    const auto unseenAfter = [](const Tour& tour) {
        return findUnseenAreas(officeMap(), cellsInView(officeMap(), tour.poses, 5.0),
                               std::vector<std::uint8_t>(officeMap().geometry().cellCount(), 0),
                               TourCoverageOptions());
    };
    const auto before = unseenAfter(officeTour()), after = unseenAfter(looking);
    ASSERT_FALSE(before.empty());
    EXPECT_LT(after.size(), before.size());
    if (!after.empty()) {
        EXPECT_LE(after.front().areaM2, before.front().areaM2);
    }
    EXPECT_EQ(looking.visitOrder.size(), looking.areas.size()) << "every room is still visited";
    EXPECT_GT(looking.length, officeTour().length);
}

TEST(TourPlanner, AShortRangeLaserIsTakenWhereItSeesWhatTheTourCountsAsSeen) {
    // A 2.5 m laser (a TurtleBot's reaches 3.5 m) sees nothing 5 m away: a tour that counted
    // such cells as seen (view_range 5) leaves them unmapped; the planned tour stops nearer.
    SimulatorConfig config;
    config.tour.coverage.lookIntoUnseen = true;
    EXPECT_EQ(plannedTour(config).coverage.viewRange, config.tour.coverage.viewRange)
        << "a 20 m laser keeps the view range";
    config.log.laser.maxRange = 2.5;
    ASSERT_EQ(plannedTour(config).coverage.viewRange, 2.5);

    const auto unseenWithinRange = [&](const Tour& tour) {
        const ClearanceMap& map = officeMap();
        const GridGeometry& g = map.geometry();
        const auto seen = cellsInView(map, tour.poses, config.log.laser.maxRange);
        double free = 0, unseen = 0;
        for (int cy = 0; cy < g.sizeY; ++cy) {
            for (int cx = 0; cx < g.sizeX; ++cx) {
                if (map.isFree(cx, cy)) {
                    ++free;
                    unseen += seen[g.index(cx, cy)] ? 0 : 1;
                }
            }
        }
        return unseen / free;
    };
    const double asConfigured = unseenWithinRange(planTour(officeMap(), config.tour));
    const double planned = unseenWithinRange(planTour(officeMap(), plannedTour(config)));
    // Measured: 12.5 % of the free cells out of the laser's sight as configured, 4.6 % planned.
    EXPECT_LT(planned, 0.5 * asConfigured) << planned << " against " << asConfigured;
}

TEST(TourPlanner, DrivesWithinTheMotionLimitsAndRecordsByDistanceAndAngle) {
    for (const Tour* t : {&officeTour(), &officeTourLookingIntoUnseen()}) {
        const Tour& tour = *t;
        SCOPED_TRACE(tour.unseen.empty() ? "room-sized areas" : "looking into unseen areas");
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
            // path step or 1 deg turn step; path steps are 5 cm, up to 7.5 cm where a leg ends:
            // resamplePolyline moves a sample within half a step of the end onto it).
            EXPECT_LE(ds, m.scanDistance + 0.075 + 1e-9);
            EXPECT_LE(dyaw, m.scanAngle + 0.1);
        }
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

namespace {
/// A 6 x 4 m room with a 1 x 2.6 m closet beside it, behind a 0.8 m door: too narrow to be a
/// room-sized area (eroded by half a door width nothing is left), mostly out of sight from the
/// room.
FloorPlan roomWithCloset() {
    FloorPlan plan = test::boxRoom(6.0, 4.0);
    plan.addWall({6.05, 2.65}, {7.2, 2.65}, 0.1);
    plan.addWall({7.15, -0.1}, {7.15, 2.7}, 0.1);
    plan.addWall({6.0, -0.05}, {7.2, -0.05}, 0.1);
    const int closet = plan.addRoom("closet", "closet", {6.1, 0.0, 7.1, 2.6});
    plan.addDoor({6.05, 1.7}, {6.05, 2.5}, 1, closet);
    return plan;
}

/// Share of the closet's free cells the laser sees from the tour's scan poses.
double closetSeen(const FloorPlan& plan, const ClearanceMap& map, const Tour& tour) {
    const std::vector<std::uint8_t> seen =
        cellsInView(map, tour.poses, TourOptions().coverage.viewRange);
    const GridGeometry& g = map.geometry();
    std::size_t cells = 0, seenCells = 0;
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            if (map.isFree(cx, cy) && plan.roomAt(g.centre(cx, cy)) == 2) {
                ++cells;
                seenCells += seen[g.index(cx, cy)];
            }
        }
    }
    return static_cast<double>(seenCells) / static_cast<double>(cells);
}
}  // namespace

TEST(TourCoverage, SightLinesStopAtTheFirstWall) {
    const FloorPlan plan = test::boxRoom(4.0, 2.0);
    const auto grid = plan.rasterise(0.05, 1.0);
    const ClearanceMap map(grid);
    const std::vector<std::uint8_t> seen = cellsInView(map, {{2.0, 1.0}}, 10.0);
    const GridGeometry& g = map.geometry();
    EXPECT_TRUE(seen[g.index(g.cellX(0.1), g.cellY(0.1))]) << "a corner of the room";
    EXPECT_TRUE(seen[g.index(g.cellX(-0.03), g.cellY(1.0))]) << "the wall's first cell";
    EXPECT_FALSE(seen[g.index(g.cellX(-0.5), g.cellY(1.0))]) << "behind the wall";
    EXPECT_FALSE(seen[g.index(g.cellX(2.0), g.cellY(2.6))]) << "behind the wall";
    // Out of range.
    EXPECT_FALSE(cellsInView(map, {{2.0, 1.0}}, 1.0)[g.index(g.cellX(0.1), g.cellY(0.1))]);
}

TEST(TourPlanner, LooksIntoAClosetTooSmallToBeARoomSizedArea) {
    const FloorPlan plan = roomWithCloset();
    const auto grid = plan.rasterise(0.05, 0.5);
    const ClearanceMap map(grid);
    TourOptions roomsOnly;
    roomsOnly.coverage.lookIntoUnseen = false;
    const Tour before = planTour(map, roomsOnly);
    ASSERT_EQ(before.areas.size(), 1u) << "the closet is no room-sized area";
    EXPECT_TRUE(before.unseen.empty());
    EXPECT_LT(closetSeen(plan, map, before), 0.6);

    TourOptions looking;
    looking.coverage.lookIntoUnseen = true;
    const Tour tour = planTour(map, looking);
    ASSERT_EQ(tour.unseen.size(), 1u);
    EXPECT_EQ(tour.unseen[0].viewpoints.size(), 1u) << "the closet's doorway";
    EXPECT_EQ(tour.unseenStops, 1u) << "the doorway is no stop of the room-sized tour";
    EXPECT_EQ(plan.roomAt(tour.unseen[0].centroid), 2) << "the unseen area is in the closet";
    EXPECT_GT(closetSeen(plan, map, tour), 0.95);
    for (const auto& p : tour.poses)
        ASSERT_GE(test::distanceToSolid(plan, {p.pose.x, p.pose.y}), roomsOnly.robotRadius);
}

TEST(TourPlanner, StaysInsideABuildingDrawnOnAFreeBackground) {
    // A plan as drawn (Bormann's, a floor plan image read as p(free) = grey): a 12 x 8 m
    // building of two rooms, its door open to a free background 4 m wide all round that runs on
    // to the map's edge. The background is the largest free area; the tour is the building's.
    mrpt::maps::COccupancyGridMap2D grid(0.0f, 20.0f, 0.0f, 16.0f, 0.05f);
    grid.fill(1.0f);
    const auto wall = [&](double x0, double y0, double x1, double y1) {
        for (int cy = grid.y2idx(y0); cy <= grid.y2idx(y1); ++cy)
            for (int cx = grid.x2idx(x0); cx <= grid.x2idx(x1); ++cx)
                grid.setCell(cx, cy, 0.0f);
    };
    const Box building{4.0, 4.0, 16.0, 12.0};
    wall(building.xMin, building.yMin, building.xMax, building.yMin + 0.1);
    wall(building.xMin, building.yMax - 0.1, building.xMax, building.yMax);
    wall(building.xMin, building.yMin, building.xMin + 0.1, building.yMax);
    wall(building.xMax - 0.1, building.yMin, building.xMax, 7.5);  // the door: 7.5 to 8.5 m
    wall(building.xMax - 0.1, 8.5, building.xMax, building.yMax);
    wall(10.0, building.yMin, 10.1, 7.5);  // the two rooms, a door between them
    wall(10.0, 8.5, 10.1, building.yMax);
    const ClearanceMap map(grid);
    for (const bool looking : {false, true}) {
        TourOptions o;
        o.coverage.lookIntoUnseen = looking;
        const Tour tour = planTour(map, o);
        ASSERT_EQ(tour.outside.size(), 1u) << "the background";
        EXPECT_TRUE(tour.areas[tour.outside[0]].openToMapEdge);
        EXPECT_EQ(tour.visitOrder.size(), 2u) << "both rooms";
        for (const auto& p : tour.poses) {
            ASSERT_TRUE(building.contains({p.pose.x, p.pose.y}))
                << "pose (" << p.pose.x << ", " << p.pose.y << ") at t=" << p.stamp
                << (looking ? ", looking into unseen areas" : "");
        }
    }
}

TEST(TourPlanner, StartsWhereItReachesTheMostRooms) {
    // Two rooms joined by a door, and apart from them a walled hall larger than either (a
    // courtyard drawn free, with no way in): the default start is in the rooms, and the tour
    // visits both of them.
    mrpt::maps::COccupancyGridMap2D grid(0.0f, 30.0f, 0.0f, 16.0f, 0.05f);
    grid.fill(0.5f);
    const auto fill = [&](double x0, double y0, double x1, double y1, float p) {
        for (int cy = grid.y2idx(y0); cy <= grid.y2idx(y1); ++cy)
            for (int cx = grid.x2idx(x0); cx <= grid.x2idx(x1); ++cx)
                grid.setCell(cx, cy, p);
    };
    fill(1.9, 1.9, 14.1, 8.1, 0.0f);  // the rooms' walls, then their floor
    fill(2.0, 2.0, 14.0, 8.0, 1.0f);
    fill(7.95, 2.0, 8.05, 4.5, 0.0f);  // the wall between them, a 1 m door at 4.5-5.5 m
    fill(7.95, 5.5, 8.05, 8.0, 0.0f);
    fill(16.9, 2.9, 27.1, 13.1, 0.0f);  // the hall
    fill(17.0, 3.0, 27.0, 13.0, 1.0f);
    const Box rooms{2.0, 2.0, 14.0, 8.0};
    const Tour tour = planTour(ClearanceMap(grid), TourOptions());
    ASSERT_EQ(tour.areas.size(), 3u);
    EXPECT_EQ(tour.visitOrder.size(), 2u) << "both rooms";
    EXPECT_EQ(tour.unreachable.size(), 1u) << "the hall";
    for (const auto& p : tour.poses) {
        ASSERT_TRUE(rooms.contains({p.pose.x, p.pose.y}))
            << "pose (" << p.pose.x << ", " << p.pose.y << ") at t=" << p.stamp;
    }
}

TEST(TourPlanner, DrivesTheClosedTourAgainLapAfterLap) {
    TourOptions o;
    o.laps = 3;
    const Tour& once = officeTour();
    const Tour thrice = planTour(officeMap(), o);
    EXPECT_EQ(thrice.visitOrder, once.visitOrder);
    EXPECT_NEAR(thrice.length, 3 * once.length, 1e-9 * once.length);
    EXPECT_EQ(thrice.legs.size(), 3 * once.legs.size());
    // Each lap passes where the first did, and the last ends where the first started.
    ASSERT_GT(thrice.poses.size(), 2 * once.poses.size());
    EXPECT_NEAR(thrice.poses.back().pose.x, once.poses.front().pose.x, 1e-9);
    EXPECT_NEAR(thrice.poses.back().pose.y, once.poses.front().pose.y, 1e-9);
    std::size_t atStart = 0;
    for (const auto& p : thrice.poses) {
        if (std::hypot(p.pose.x - once.poses.front().pose.x, p.pose.y - once.poses.front().pose.y) <
            1e-9)
            ++atStart;
    }
    EXPECT_GE(atStart, 4u);  // the start and the end of each of the three laps
    // Laps need a closed tour.
    o.returnToStart = false;
    EXPECT_THROW(planTour(officeMap(), o), std::invalid_argument);
}
