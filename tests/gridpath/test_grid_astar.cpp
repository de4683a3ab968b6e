// gridpath::GridAStar, the grid search under the simulator's tours and the planner's reference
// paths: exact costs on known rasters, corners, weights, A* agreeing with Dijkstra, and
// Dijkstra's radix heap giving the very costs a binary heap gives. gridpath::RadixHeap's order.
#include <toposlam/gridpath/GridAStar.h>
#include <toposlam/gridpath/RadixHeap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <random>
#include <string>
#include <utility>
#include <vector>

using toposlam::gridpath::GridAStar;
using toposlam::gridpath::RadixHeap;

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

/// A random raster: a quarter of the cells blocked, the others with step costs in [1, 4) that
/// are no round numbers, so float sums round differently along different paths.
struct RandomRaster {
    int cols, rows;
    std::vector<float> cost;
};
RandomRaster randomRaster(unsigned seed, int cols, int rows) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    RandomRaster r{cols, rows, {}};
    for (int i = 0; i < cols * rows; ++i)
        r.cost.push_back(u(rng) < 0.25f ? 0.0f : 1.0f + 3.0f * u(rng));
    r.cost[0] = 1.0f;
    return r;
}

/// Dijkstra as the textbook writes it (std::priority_queue, bounds and corners tested per
/// move), with the same float steps: the reference for GridAStar's costs, to the bit.
std::vector<float> referenceCosts(const RandomRaster& r, float cellSize, std::size_t start) {
    const auto free = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < r.cols && y < r.rows && r.cost[y * r.cols + x] > 0;
    };
    std::vector<float> d(r.cost.size(), GridAStar::kUnreachable);
    std::vector<bool> done(r.cost.size(), false);
    using Entry = std::pair<float, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    d[start] = 0;
    queue.push({0.0f, start});
    while (!queue.empty()) {
        const std::size_t c = queue.top().second;
        queue.pop();
        if (done[c])
            continue;
        done[c] = true;
        const int x = static_cast<int>(c) % r.cols, y = static_cast<int>(c) / r.cols;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const bool diagonal = dx != 0 && dy != 0;
                if ((dx == 0 && dy == 0) || !free(x + dx, y + dy) ||
                    (diagonal && (!free(x + dx, y) || !free(x, y + dy))))
                    continue;
                const std::size_t n = static_cast<std::size_t>((y + dy) * r.cols + x + dx);
                const float step = (diagonal ? 1.41421356f : 1.0f) * cellSize;
                const float c2 = d[c] + step * r.cost[n];
                if (!done[n] && c2 < d[n]) {
                    d[n] = c2;
                    queue.push({c2, n});
                }
            }
        }
    }
    return d;
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

TEST(GridAStar, DijkstrasCostsAreTheTextbooksToTheBit) {
    // The radix heap settles cells of equal cost in another order than a binary heap; the
    // costs must not change by one bit (the simulator's tours are ordered by them).
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const RandomRaster r = randomRaster(seed, 60, 45);
        GridAStar search(r.cols, r.rows, 0.05, r.cost);
        for (const std::size_t start : {std::size_t{0}, std::size_t{1349}, std::size_t{2699}}) {
            if (r.cost[start] == 0)
                continue;
            const std::vector<float> expected = referenceCosts(r, 0.05f, start);
            const std::vector<float>& costs = search.costsFrom(start);
            ASSERT_EQ(costs.size(), expected.size());
            for (std::size_t c = 0; c < costs.size(); ++c)
                ASSERT_EQ(costs[c], expected[c])
                    << "seed " << seed << " start " << start << " cell " << c;
        }
    }
}

TEST(GridAStar, CostsToTheTargetsAreCostsFromsForThem) {
    const RandomRaster r = randomRaster(11, 80, 50);
    GridAStar search(r.cols, r.rows, 0.05, r.cost);
    std::mt19937 rng(3);
    std::uniform_int_distribution<std::size_t> anyCell(0, r.cost.size() - 1);
    for (int trial = 0; trial < 6; ++trial) {
        std::size_t start = anyCell(rng);
        while (r.cost[start] == 0)
            start = anyCell(rng);
        // Near and far targets, blocked ones, one twice and one outside the grid.
        std::vector<std::size_t> targets;
        for (int k = 0; k < 5; ++k)
            targets.push_back(anyCell(rng));
        targets.push_back(start + 1 < r.cost.size() ? start + 1 : start - 1);
        targets.push_back(targets.front());
        targets.push_back(r.cost.size() + 7);
        const std::vector<float> to = search.costsTo(start, targets);
        const std::vector<float> all = search.costsFrom(start);  // a copy: costsTo reuses state
        ASSERT_EQ(to.size(), targets.size());
        for (std::size_t i = 0; i + 1 < targets.size(); ++i)
            EXPECT_EQ(to[i], all[targets[i]]) << "trial " << trial << " target " << targets[i];
        EXPECT_EQ(to.back(), GridAStar::kUnreachable);
    }
    // A blocked start reaches nothing, and no target is no work.
    std::size_t blocked = 0;
    while (r.cost[blocked] != 0)
        ++blocked;
    for (const float c : search.costsTo(blocked, {0, 1, 2}))
        EXPECT_EQ(c, GridAStar::kUnreachable);
    EXPECT_TRUE(search.costsTo(0, {}).empty());
}

TEST(RadixHeap, PopsEveryKeyInOrderWhilePushesFollowThePops) {
    // As Dijkstra uses it: each pop may push keys no smaller than the key just popped.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> step(0.0f, 2.0f);
    RadixHeap heap;
    std::priority_queue<float, std::vector<float>, std::greater<>> reference;
    std::vector<float> keyOf(1);
    heap.push(0.0f, 0);
    reference.push(0.0f);
    int popped = 0;
    while (!heap.empty()) {
        ASSERT_FALSE(reference.empty());
        const float key = keyOf[heap.pop()];
        EXPECT_EQ(key, reference.top()) << "pop " << popped;
        reference.pop();
        ++popped;
        for (int k = 0; k < 3 && keyOf.size() < 5000; ++k) {
            // Equal keys too (a zero step), and keys far above the rest.
            const float next = k == 2 ? key : key + (k == 1 ? 100.0f * step(rng) : step(rng));
            keyOf.push_back(next);
            heap.push(next, static_cast<std::uint32_t>(keyOf.size() - 1));
            reference.push(next);
        }
    }
    EXPECT_TRUE(reference.empty());
    EXPECT_EQ(popped, 5000);
    heap.clear();  // and it starts again from any key
    heap.push(3.5f, 7);
    heap.push(1.25f, 8);
    EXPECT_EQ(heap.pop(), 8u);
    EXPECT_EQ(heap.pop(), 7u);
    EXPECT_TRUE(heap.empty());
}
