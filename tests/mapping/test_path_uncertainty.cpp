// PathUncertainty answers lazily (to(): the search goes only as far as the node asked for) what
// the whole search (from()) answers, in any order of questions, through loops, withdrawn edges
// and parts of the graph no edge joins.
#include <toposlam/mapping/PathUncertainty.h>
#include <toposlam/mapping/PoseGraph.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

using mrpt::poses::CPose2D;
using toposlam::mapping::EdgeKind;
using toposlam::mapping::PathUncertainty;
using toposlam::mapping::PathVariance;
using toposlam::mapping::PoseGraph;

namespace {

mrpt::math::CMatrixDouble33 covariance(std::mt19937& rng) {
    std::uniform_real_distribution<double> position(1e-5, 1e-2), heading(1e-6, 1e-3);
    mrpt::math::CMatrixDouble33 c = mrpt::math::CMatrixDouble33::Zero();
    c(0, 0) = position(rng);
    c(1, 1) = position(rng);
    c(2, 2) = heading(rng);
    return c;
}

// A chain of `n` keyframes 0.3 m apart with loops between random pairs, some withdrawn, and
// `isolated` more nodes joined to nothing.
PoseGraph randomGraph(std::size_t n, std::size_t loops, std::size_t isolated, unsigned seed) {
    std::mt19937 rng(seed);
    PoseGraph g;
    for (std::size_t i = 0; i < n + isolated; ++i)
        g.addNode(CPose2D(0.3 * double(i), 0, 0));
    for (std::size_t i = 1; i < n; ++i)
        g.addEdge(i - 1, i, CPose2D(0.3, 0, 0), covariance(rng), EdgeKind::Registration);
    std::uniform_int_distribution<std::size_t> node(0, n - 1);
    for (std::size_t k = 0; k < loops; ++k) {
        const std::size_t a = node(rng), b = node(rng);
        if (a == b)
            continue;
        const std::size_t e = g.addEdge(std::min(a, b), std::max(a, b), CPose2D(0.1, 0.2, 0.05),
                                        covariance(rng), EdgeKind::Loop);
        if (k % 7 == 0)
            g.withdrawEdge(e);
    }
    return g;
}

void expectSame(const PathVariance& lazy, const PathVariance& full, std::size_t node) {
    EXPECT_EQ(lazy.reached, full.reached) << "node " << node;
    EXPECT_EQ(lazy.position, full.position) << "node " << node;  // the same sums, bit for bit
    EXPECT_EQ(lazy.heading, full.heading) << "node " << node;
}

}  // namespace

TEST(PathUncertainty, LazyAnswersAreTheWholeSearchsInAnyOrder) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const PoseGraph g = randomGraph(300, 60, 5, seed);
        PathUncertainty whole(0.05, 0.01), lazy(0.05, 0.01);
        const std::size_t source = 250;
        const std::vector<PathVariance> full = whole.from(g, source);
        ASSERT_EQ(full.size(), g.nodeCount());
        // Nearest first, then the rest at random, then everything again (already settled).
        std::vector<std::size_t> order(g.nodeCount());
        std::iota(order.begin(), order.end(), 0);
        std::mt19937 rng(seed);
        std::shuffle(order.begin() + 10, order.end(), rng);
        lazy.start(g, source);
        for (std::size_t node : order)
            expectSame(lazy.to(node), full[node], node);
        for (std::size_t node : order)
            expectSame(lazy.to(node), full[node], node);
        // The nodes no edge joins are not reached; the source is, with no uncertainty.
        for (std::size_t node = 300; node < g.nodeCount(); ++node)
            EXPECT_FALSE(full[node].reached);
        EXPECT_TRUE(full[source].reached);
        EXPECT_EQ(full[source].position, 0.0);
    }
}

TEST(PathUncertainty, UncertaintyGrowsAlongTheChainAndALoopShortensIt) {
    PoseGraph g = randomGraph(200, 0, 0, 1);
    PathUncertainty u(0.05, 0.01);
    u.start(g, 199);
    const double far = u.to(0).position, near = u.to(190).position;
    EXPECT_GT(far, near);
    EXPECT_GT(near, 0.0);
    std::mt19937 rng(2);
    g.addEdge(0, 199, CPose2D(0.1, 0, 0), covariance(rng), EdgeKind::Loop);
    u.start(g, 199);
    EXPECT_LT(u.to(0).position, far / 10);
    EXPECT_EQ(u.to(190).position, near);  // nearer along the chain than through the loop
}

// Where the edges' own covariances are smaller, each edge of length l adds (a l)^2 and (b l)^2,
// whatever it turns (the loop gate's model, PathUncertainty.h).
TEST(PathUncertainty, EdgesWithTinyCovariancesAddTheDriftModelsVariances) {
    const double a = 0.05, b = 0.01, step = 0.3;
    mrpt::math::CMatrixDouble33 tiny = mrpt::math::CMatrixDouble33::Zero();
    tiny(0, 0) = tiny(1, 1) = tiny(2, 2) = 1e-12;
    for (const double turn : {0.0, 0.25}) {
        SCOPED_TRACE("turn " + std::to_string(turn));
        PoseGraph g;
        for (std::size_t i = 0; i <= 10; ++i)
            g.addNode(CPose2D());  // node poses do not enter the search, only the edges
        for (std::size_t i = 1; i <= 10; ++i)
            g.addEdge(i - 1, i, CPose2D(step, 0, turn), tiny, EdgeKind::Registration);
        PathUncertainty u(a, b);
        u.start(g, 0);
        EXPECT_NEAR(u.to(10).position, 10 * a * a * step * step, 1e-15);
        EXPECT_NEAR(u.to(10).heading, 10 * b * b * step * step, 1e-15);
        EXPECT_NEAR(u.to(4).position, 4 * a * a * step * step, 1e-15);
    }
}
