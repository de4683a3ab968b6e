// gridpath::GridAStar, the grid search under the simulator's tours and the planner's reference
// paths: exact costs on known rasters, corners, weights, and A* agreeing with Dijkstra.
#include <toposlam/gridpath/GridAStar.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using toposlam::gridpath::GridAStar;

namespace {

// '#' blocked, '.' cost 1, digits 2-9: that step cost; row 0 first (index y * cols + x).
GridAStar gridOf(const std::vector<std::string>& rows, double cellSize = 1.0) {
    std::vector<float> cost;
    for (const std::string& r : rows) {
        for (const char c : r)
            cost.push_back(c == '#' ? 0.0f : c == '.' ? 1.0f : static_cast<float>(c - '0'));
    }
    return GridAStar(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), cellSize,
                     cost);
}

}  // namespace

TEST(GridAStar, OpenGridCostIsTheOctileDistance) {
    GridAStar g = gridOf(std::vector<std::string>(20, std::string(30, '.')), 0.05);
    const auto p = g.path(g.index(2, 3), g.index(27, 10));
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->cost, 0.05 * ((25 - 7) + std::sqrt(2.0) * 7), 1e-5);
    EXPECT_EQ(p->cells.front(), g.index(2, 3));
    EXPECT_EQ(p->cells.back(), g.index(27, 10));
    EXPECT_EQ(p->cells.size(), 26u);  // one cell per step of the longer axis
    const auto same = g.path(g.index(4, 4), g.index(4, 4));
    ASSERT_TRUE(same);
    EXPECT_EQ(same->cells.size(), 1u);
    EXPECT_EQ(same->cost, 0.0);
}

TEST(GridAStar, NeverCutsABlockedCorner) {
    GridAStar g = gridOf({"..", "#."});
    // (0,0) -> (1,1) diagonally would touch the blocked (0,1): go round, 2 straight steps.
    const auto p = g.path(g.index(0, 0), g.index(1, 1));
    ASSERT_TRUE(p);
    EXPECT_DOUBLE_EQ(p->cost, 2.0);
    GridAStar sealed = gridOf({".#", "#."});
    EXPECT_FALSE(sealed.path(sealed.index(0, 0), sealed.index(1, 1)));
}

TEST(GridAStar, StepCostsSteerThePath) {
    // The direct row costs 9 per cell; the detour through the cheap rows wins.
    GridAStar g = gridOf({".......", ".99999.", "......."});
    const auto p = g.path(g.index(0, 1), g.index(6, 1));
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->cost, 4 + 2 * std::sqrt(2.0), 1e-5);  // up, across, down
    for (std::size_t k = 1; k + 1 < p->cells.size(); ++k)
        EXPECT_NE(p->cells[k] / 7, 1u) << "a cell of the expensive row between the ends";
}

TEST(GridAStar, BlockedOrDisconnectedEndsHaveNoPath) {
    GridAStar g = gridOf({"..#..", "..#..", "..#.."});
    EXPECT_FALSE(g.path(g.index(0, 0), g.index(4, 2)));
    EXPECT_FALSE(g.path(g.index(2, 0), g.index(0, 0)));  // start blocked
    EXPECT_FALSE(g.path(g.index(0, 0), 99));             // outside
    const auto& costs = g.costsFrom(g.index(0, 0));
    EXPECT_EQ(costs[g.index(4, 0)], GridAStar::kUnreachable);
    EXPECT_EQ(costs[g.index(2, 1)], GridAStar::kUnreachable);
    EXPECT_FLOAT_EQ(costs[g.index(1, 2)], 1 + std::sqrt(2.0f));
    for (const float c : g.costsFrom(g.index(2, 1)))
        EXPECT_EQ(c, GridAStar::kUnreachable);
}

TEST(GridAStar, AStarAgreesWithDijkstraOnRandomRasters) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> cell(0, 3);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<std::string> rows(25, std::string(40, '.'));
        for (auto& r : rows) {
            for (char& c : r)
                c = "#.3."[cell(rng)];
        }
        rows[0][0] = '.';
        GridAStar open = gridOf(rows, 0.1);
        const std::size_t start = open.index(0, 0);
        const std::vector<float> all = open.costsFrom(start);  // a copy: path() reuses state
        for (std::size_t goal = 0; goal < all.size(); goal += 7) {
            const auto p = open.path(start, goal);
            ASSERT_EQ(p.has_value(), all[goal] != GridAStar::kUnreachable) << goal;
            if (!p)
                continue;
            EXPECT_NEAR(p->cost, all[goal], 1e-4) << goal;
            // A caller's heuristic (here none at all: Dijkstra) finds the same cost.
            const auto q = open.path(start, goal, [](std::size_t) { return 0.0f; });
            ASSERT_TRUE(q);
            EXPECT_NEAR(q->cost, all[goal], 1e-4) << goal;
        }
    }
}

TEST(GridAStar, RefusesInvalidStepCosts) {
    EXPECT_THROW(GridAStar(2, 2, 1.0, {1, 1, 1}), std::invalid_argument);
    EXPECT_THROW(GridAStar(2, 1, 1.0, {1, 0.5f}), std::invalid_argument);
    EXPECT_THROW(GridAStar(2, 1, 0.0, {1, 1}), std::invalid_argument);
}
