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
    EXPECT_EQ(lazy.swung, full.swung) << "node " << node;
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

// Back round a U, the current keyframe is close to the first one, but the chain between them
// went 9 m away: a heading error out there swings the current keyframe, seen from the first,
// by its lever arm. The swung variance is the largest eigenvalue of
//   sum over edges of (a l)^2 I + (b l)^2 w w^T,  w = the lever from where the error enters
// to the source, turned by 90 deg,
// which the search builds edge by edge (first-order pose compounding), and which is far more
// than the position + heading d^2 of the two keyframes' distance d.
TEST(PathUncertainty, AHeadingErrorFarAlongTheChainSwingsTheSourceByItsLeverArm) {
    const double a = 0.01, b = 0.01, step = 0.3;
    const int n = 30;  // steps out and back
    mrpt::math::CMatrixDouble33 tiny = mrpt::math::CMatrixDouble33::Zero();
    tiny(0, 0) = tiny(1, 1) = tiny(2, 2) = 1e-12;
    std::vector<CPose2D> poses;
    for (int i = 0; i <= n; ++i)
        poses.emplace_back(step * i, 0, 0);  // out along x
    for (int i = 1; i <= 2; ++i)
        poses.emplace_back(step * n, step * i, M_PI / 2);  // across
    for (int i = 1; i <= n; ++i)
        poses.emplace_back(step * (n - i), 0.6, M_PI);  // and back
    PoseGraph g;
    for (const CPose2D& p : poses)
        g.addNode(p);
    for (std::size_t i = 1; i < poses.size(); ++i)
        g.addEdge(i - 1, i, poses[i] - poses[i - 1], tiny, EdgeKind::Registration);

    const std::size_t source = poses.size() - 1;  // (0, 0.6): 0.6 m from node 0
    PathUncertainty u(a, b);
    u.start(g, source);
    const PathVariance& v = u.to(0);
    // Searched from the source, the error of the edge between nodes k and k + 1 enters at
    // node k.
    double sxx = 0, syy = 0, sxy = 0;
    for (std::size_t k = 0; k < source; ++k) {
        const double l = (poses[k + 1] - poses[k]).norm();
        const double q = std::max(b * b * l * l, 1e-12), p = std::max(a * a * l * l, 1e-12);
        const double wx = poses[k].y() - poses[source].y(), wy = poses[source].x() - poses[k].x();
        sxx += p + q * wx * wx, syy += p + q * wy * wy, sxy += q * wx * wy;
    }
    const double largest =
        0.5 * (sxx + syy) + std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
    EXPECT_NEAR(v.swung, largest, 1e-9 * largest);
    const double d = 0.6;
    EXPECT_GT(v.swung, 10 * v.at(d));
    // Straight out, the old bound (all heading error at the far end) is the larger one.
    u.start(g, n);
    const double sumOfSquares = n * (n + 1) * (2 * n + 1) / 6.0;  // levers of 1..n steps
    EXPECT_LT(u.to(0).swung, u.to(0).at(step * n));
    EXPECT_NEAR(u.to(0).swung, u.to(0).position + b * b * step * step * step * step * sumOfSquares,
                1e-12);
}
