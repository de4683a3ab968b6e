#include <gtest/gtest.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/GridGeometry.h>
#include <toposlam/simulation/OfficeFloorPlan.h>

#include <deque>
#include <set>

using mrpt::math::TPoint2D;
using namespace toposlam::simulation;

TEST(OfficeFloorPlan, HasACorridorAndSixToTenRoomsWithRealisticDoors) {
    const FloorPlan plan = makeOfficeFloorPlan();
    ASSERT_FALSE(plan.rooms().empty());
    EXPECT_EQ(plan.rooms().front().kind, "corridor");
    const std::size_t rooms = plan.rooms().size() - 1;
    EXPECT_GE(rooms, 6u);
    EXPECT_LE(rooms, 10u);
    std::set<long> areas;  // rooms of different sizes
    for (const FloorRoom& r : plan.rooms())
        areas.insert(std::lround(r.floor.area()));
    EXPECT_GE(areas.size(), rooms - 1);
    for (const FloorDoor& d : plan.doors()) {
        EXPECT_GE(d.width, 0.8 - 1e-9) << "door " << d.id;
        EXPECT_LE(d.width, 1.0 + 1e-9) << "door " << d.id;
        EXPECT_NE(d.roomA, d.roomB);
        // Half a metre either side of the door's middle lies in the two rooms it joins.
        const TPoint2D mid((d.jambA.x + d.jambB.x) / 2, (d.jambA.y + d.jambB.y) / 2);
        const double nx = d.jambA.y == d.jambB.y ? 0.0 : 0.5, ny = 0.5 - nx;
        const std::set<int> sides{plan.roomAt({mid.x + nx, mid.y + ny}),
                                  plan.roomAt({mid.x - nx, mid.y - ny})};
        EXPECT_EQ(sides, (std::set<int>{d.roomA, d.roomB})) << "door " << d.id;
        EXPECT_FALSE(plan.isSolid(mid)) << "door " << d.id << " is open";
    }
    EXPECT_FALSE(plan.furnitureBoxes().empty());
}

TEST(OfficeFloorPlan, RasterIsClosedConnectedAndLabelledPerRoom) {
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(0.05, 0.5);
    const GridGeometry g = GridGeometry::of(grid);
    const ClearanceMap map(grid);
    const auto labels = plan.roomLabels(grid);

    // Flood fill the free cells from the corridor: through the doors it reaches every room and
    // never leaves the building.
    const FloorRoom& corridor = plan.rooms().front();
    const int sx = g.cellX((corridor.floor.xMin + corridor.floor.xMax) / 2);
    const int sy = g.cellY((corridor.floor.yMin + corridor.floor.yMax) / 2);
    std::vector<std::uint8_t> seen(g.cellCount(), 0);
    std::deque<std::pair<int, int>> queue{{sx, sy}};
    seen[g.index(sx, sy)] = 1;
    std::set<int> reached;
    std::size_t reachedCells = 0;
    const Box building = plan.extent();
    while (!queue.empty()) {
        const auto [cx, cy] = queue.front();
        queue.pop_front();
        ++reachedCells;
        ASSERT_TRUE(building.contains(g.centre(cx, cy))) << "free space leaks out of the building";
        reached.insert(labels[g.index(cx, cy)]);
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            const int nx = cx + dx, ny = cy + dy;
            if (!map.isFree(nx, ny) || seen[g.index(nx, ny)])
                continue;
            seen[g.index(nx, ny)] = 1;
            queue.push_back({nx, ny});
        }
    }
    reached.erase(0);  // doorways
    EXPECT_EQ(reached.size(), plan.rooms().size());
    EXPECT_EQ(reachedCells, map.freeCellCount()) << "every free cell is reachable";

    // Label areas equal the room floors (both are exact multiples of the cell).
    for (const FloorRoom& r : plan.rooms()) {
        const auto cells = std::count(labels.begin(), labels.end(), r.id);
        EXPECT_NEAR(cells * 0.05 * 0.05, r.floor.area(), 1e-6) << r.name;
    }
}

TEST(OfficeFloorPlan, JsonListsEveryRoomAndDoor) {
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto grid = plan.rasterise(0.05, 0.5);
    const std::string json = plan.toJson(grid, "office.gridmap.gz", "office_rooms.png");
    std::size_t jambs = 0, kinds = 0;
    for (std::size_t p = 0; (p = json.find("\"jambs\"", p)) != std::string::npos; ++p)
        ++jambs;
    for (std::size_t p = 0; (p = json.find("\"kind\"", p)) != std::string::npos; ++p)
        ++kinds;
    EXPECT_EQ(jambs, plan.doors().size());
    EXPECT_EQ(kinds, plan.rooms().size());
    EXPECT_NE(json.find("\"name\": \"corridor\""), std::string::npos);
}
