// PathUncertainty answers lazily (to(): the search goes only as far as the node asked for) what
// the whole search (from()) answers, in any order of questions, through loops, withdrawn edges
// and parts of the graph no edge joins.
#include <toposlam/mapping/PathUncertainty.h>
#include <toposlam/mapping/PoseGraph.h>

#include <gtest/gtest.h>

#include <Eigen/Dense>

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

/// m^2: the largest variance of the position in `c`.
double largestPositionVariance(const PathVariance::Covariance& c) {
    const double half = 0.5 * (c.xx - c.yy);
    return 0.5 * (c.xx + c.yy) + std::sqrt(half * half + c.xy * c.xy);
}

void expectSame(const PathVariance& lazy, const PathVariance& full, std::size_t node) {
    EXPECT_EQ(lazy.reached, full.reached) << "node " << node;
    EXPECT_EQ(lazy.position, full.position) << "node " << node;  // the same sums, bit for bit
    EXPECT_EQ(lazy.heading, full.heading) << "node " << node;
    EXPECT_EQ(lazy.swung.xx, full.swung.xx) << "node " << node;
    EXPECT_EQ(lazy.swung.xy, full.swung.xy) << "node " << node;
    EXPECT_EQ(lazy.swung.yh, full.swung.yh) << "node " << node;
    EXPECT_EQ(lazy.swung.hh, full.swung.hh) << "node " << node;
    EXPECT_EQ(lazy.reach, full.reach) << "node " << node;
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

/// Out 9 m along x in steps of `step`, two steps across, and back: the last pose is 0.6 m
/// from the first. Registration edges with a negligible covariance (the drift model's floor
/// is all there is).
struct UTurn {
    std::vector<CPose2D> poses;
    PoseGraph graph;
};

UTurn uTurn(double step, int n) {
    mrpt::math::CMatrixDouble33 tiny = mrpt::math::CMatrixDouble33::Zero();
    tiny(0, 0) = tiny(1, 1) = tiny(2, 2) = 1e-12;
    UTurn u;
    for (int i = 0; i <= n; ++i)
        u.poses.emplace_back(step * i, 0, 0);  // out along x
    for (int i = 1; i <= 2; ++i)
        u.poses.emplace_back(step * n, step * i, M_PI / 2);  // across
    for (int i = 1; i <= n; ++i)
        u.poses.emplace_back(step * (n - i), 0.6, M_PI);  // and back
    for (const CPose2D& p : u.poses)
        u.graph.addNode(p);
    for (std::size_t i = 1; i < u.poses.size(); ++i)
        u.graph.addEdge(i - 1, i, u.poses[i] - u.poses[i - 1], tiny, EdgeKind::Registration);
    return u;
}

// Back round a U, the current keyframe is close to the first one, but the chain between them
// went 9 m away: a heading error out there swings the current keyframe, seen from the first,
// by its lever arm. The swung covariance is (world axes, before it is turned into the source's
// frame)
//   sum over edges of (a l)^2 diag(1, 1, 0) + (b l)^2 (w, 1) (w, 1)^T,  w = the lever from
// where the error enters to the source, turned by 90 deg,
// which the search builds edge by edge (first-order pose compounding); its position part is far
// more than the position + heading d^2 of the two keyframes' distance d.
TEST(PathUncertainty, AHeadingErrorFarAlongTheChainSwingsTheSourceByItsLeverArm) {
    const double a = 0.01, b = 0.01, step = 0.3;
    const int n = 30;  // steps out and back
    const UTurn turn = uTurn(step, n);
    const std::vector<CPose2D>& poses = turn.poses;
    const PoseGraph& g = turn.graph;

    const std::size_t source = poses.size() - 1;  // (0, 0.6): 0.6 m from node 0
    PathUncertainty u(a, b);
    u.start(g, source);
    const PathVariance& v = u.to(0);
    // Searched from the source, the error of the edge between nodes k and k + 1 enters at
    // node k.
    double sxx = 0, syy = 0, sxy = 0, sxh = 0, syh = 0, shh = 0;
    for (std::size_t k = 0; k < source; ++k) {
        const double l = (poses[k + 1] - poses[k]).norm();
        const double q = std::max(b * b * l * l, 1e-12), p = std::max(a * a * l * l, 1e-12);
        const double wx = poses[k].y() - poses[source].y(), wy = poses[source].x() - poses[k].x();
        sxx += p + q * wx * wx, syy += p + q * wy * wy, sxy += q * wx * wy;
        sxh += q * wx, syh += q * wy, shh += q;
    }
    const double largest =
        0.5 * (sxx + syy) + std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
    EXPECT_NEAR(largestPositionVariance(v.swung), largest, 1e-9 * largest);
    // In the source's frame: it heads back along -x, so x and y change sign.
    EXPECT_NEAR(v.swung.xx, sxx, 1e-9 * sxx);
    EXPECT_NEAR(v.swung.yy, syy, 1e-9 * sxx);
    EXPECT_NEAR(v.swung.xy, sxy, 1e-9 * sxx);
    EXPECT_NEAR(v.swung.xh, -sxh, 1e-9 * std::abs(sxh));
    EXPECT_NEAR(v.swung.yh, -syh, 1e-9 * std::abs(syh) + 1e-15);
    EXPECT_NEAR(v.swung.hh, shh, 1e-12 * shh);
    const double d = 0.6;
    EXPECT_GT(largestPositionVariance(v.swung), 10 * v.at(d));
    // Straight out, the old bound (all heading error at the far end) is the larger one.
    u.start(g, n);
    const double sumOfSquares = n * (n + 1) * (2 * n + 1) / 6.0;  // levers of 1..n steps
    EXPECT_LT(largestPositionVariance(u.to(0).swung), u.to(0).at(step * n));
    EXPECT_NEAR(largestPositionVariance(u.to(0).swung),
                u.to(0).position + b * b * step * step * step * step * sumOfSquares, 1e-12);
}

// What the correlation is for. Back round the U, a heading error at the far end moves the
// current keyframe across the U and turns it alike; a shift as long without that turn is what
// a look-alike place gives (a corridor matched one door along). Both are as far from the
// first keyframe's view of it; only the first fits the swung covariance.
TEST(PathUncertainty, AShiftWithoutTheTurnThatWouldExplainItStaysOutsideTheSwungCovariance) {
    const double a = 0.01, b = 0.01, step = 0.3;
    const int n = 30;
    const UTurn turn = uTurn(step, n);
    const std::size_t source = turn.poses.size() - 1;
    PathUncertainty u(a, b);
    u.start(turn.graph, source);
    const PathVariance::Covariance& c = u.to(0).swung;
    Eigen::Matrix3d cov;
    cov << c.xx, c.xy, c.xh, c.xy, c.yy, c.yh, c.xh, c.yh, c.hh;
    const auto mahalanobis = [&](const Eigen::Vector3d& e) { return e.dot(cov.ldlt().solve(e)); };
    // Two sigmas of the chain's heading, all at the far end of the U (node n): the source
    // swings about it by the lever from there, turned by 90 deg, and by the source's heading
    // (pi) into its own frame.
    const double turnError = 2 * std::sqrt(c.hh);
    const CPose2D& far = turn.poses[static_cast<std::size_t>(n)];
    const CPose2D& here = turn.poses[source];
    const Eigen::Vector2d swungBy(-turnError * (far.y() - here.y()),
                                  -turnError * (here.x() - far.x()));
    const Eigen::Vector3d drift(swungBy.x(), swungBy.y(), turnError);
    const Eigen::Vector3d lookAlike(swungBy.x(), swungBy.y(), 0);
    // The farthest the chain went from the source, the longest lever: the U's far corner.
    EXPECT_NEAR(u.to(0).reach, std::hypot(step * n, 0.6), 1e-9);
    const double gate = 16.27;  // loop_chi2
    // Far outside the gate without the lever arm (the two keyframes are 0.6 m apart) ...
    EXPECT_GT(swungBy.squaredNorm() / u.to(0).at(0.6), 10 * gate);
    // ... inside it with the swung covariance, but only with the turn.
    EXPECT_LT(mahalanobis(drift), gate);
    EXPECT_GT(mahalanobis(lookAlike), 2 * gate);
}
