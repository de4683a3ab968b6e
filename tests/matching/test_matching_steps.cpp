// Unit tests of the matcher's steps on hand-made geometry.
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/AttributedGraph.h>
#include <toposlam/matching/GraphScanMatcher.h>
#include <toposlam/matching/GreedyAssignment.h>
#include <toposlam/matching/HoughPoseSearch.h>
#include <toposlam/matching/RigidTransform2D.h>
#include <toposlam/matching/Similarity.h>
#include <toposlam/matching/SpgmSolver.h>

#include <cmath>
#include <random>

#include "SyntheticScans.h"

using mrpt::math::TPoint2D;
using mrpt::poses::CPose2D;
using namespace toposlam::matching;

namespace {
toposlam::features::LineSegment seg(double x0, double y0, double x1, double y1) {
    toposlam::features::LineSegment s;
    s.start = {x0, y0};
    s.end = {x1, y1};
    return s;
}

std::vector<toposlam::features::LineSegment> transformed(
    const std::vector<toposlam::features::LineSegment>& in, const CPose2D& T) {
    std::vector<toposlam::features::LineSegment> out = in;
    for (auto& s : out) {
        T.composePoint(s.start.x, s.start.y, s.start.x, s.start.y);
        T.composePoint(s.end.x, s.end.y, s.end.x, s.end.y);
    }
    return out;
}

// Five walls of different lengths and directions (no symmetry).
std::vector<toposlam::features::LineSegment> someSegments() {
    return {seg(1, -2, 4, -2), seg(4, -1, 4, 3), seg(3, 3.5, -1, 3.5), seg(-2, 2, -2, -0.5),
            seg(0.5, 0.5, 1.7, 1.4)};
}
}  // namespace

TEST(AttributedGraph, EdgeAttributesAreRotationInvariantAndAntisymmetric) {
    const auto segs = someSegments();
    AttributedGraph g, h;
    g.build(segs);
    h.build(transformed(segs, CPose2D(2.0, -1.0, 2.5)));
    ASSERT_EQ(g.size(), 5u);
    for (std::size_t i = 0; i < g.size(); ++i) {
        EXPECT_NEAR(g.node(i).length, h.node(i).length, 1e-12);
        for (std::size_t j = 0; j < g.size(); ++j) {
            if (i == j)
                continue;
            for (std::size_t a = 0; a < AttributedGraph::kEdgeAttributes; ++a) {
                const double d = g.edge(i, j)[a] - h.edge(i, j)[a];
                EXPECT_NEAR(a == 0 ? mrpt::math::wrapToPi(d) : d, 0.0, 1e-9);
            }
            EXPECT_NEAR(mrpt::math::wrapToPi(g.edge(i, j)[0] + g.edge(j, i)[0]), 0.0, 1e-12);
            EXPECT_NEAR(g.edge(i, j)[1], -g.edge(j, i)[1], 1e-12);
        }
    }
    // Walls 0 and 1 meet near (4, -2): closest distance is the 1 m gap; 0 -> 1 turns +90 deg.
    EXPECT_NEAR(g.edge(0, 1)[AttributedGraph::ClosestDistance], 1.0, 1e-12);
    EXPECT_NEAR(g.edge(0, 1)[AttributedGraph::Angle], M_PI / 2, 1e-12);
    EXPECT_NEAR(g.edge(0, 1)[AttributedGraph::MidpointDistance], std::hypot(1.5, 3.0), 1e-12);
}

TEST(AttributedGraph, KeepsTheLongestSegments) {
    AttributedGraph g;
    g.build(someSegments(), 0.0, 3);
    ASSERT_EQ(g.size(), 3u);
    for (const SegmentNode& n : g.nodes())
        EXPECT_GE(n.length, 3.0);
    g.build(someSegments(), 2.0);
    EXPECT_EQ(g.size(), 4u);
}

TEST(RigidTransform2D, ExactFromPointsAndLines) {
    const CPose2D truth(1.3, -0.7, 2.2);
    std::vector<PointPair> points;
    for (const TPoint2D& p : {TPoint2D(0, 0), TPoint2D(3, 1), TPoint2D(-1, 2), TPoint2D(2, -4)}) {
        TPoint2D q;
        truth.composePoint(p.x, p.y, q.x, q.y);
        points.push_back({p, q, 1.0});
    }
    const TransformEstimate fp = rigidTransformFromPoints(points);
    ASSERT_TRUE(fp.valid);
    EXPECT_NEAR((fp.pose - truth).norm(), 0.0, 1e-12);
    EXPECT_NEAR(mrpt::math::wrapToPi(fp.pose.phi() - truth.phi()), 0.0, 1e-12);

    // Lines: midpoints deliberately far apart along each line (occlusion): still exact.
    const auto cur = someSegments();
    const auto ref = transformed(cur, truth);
    AttributedGraph gc, gr;
    gc.build(cur);
    gr.build(ref);
    std::vector<LinePair> lines;
    for (std::size_t i = 0; i < 2; ++i) {
        const SegmentNode& c = gc.node(i);
        const SegmentNode& r = gr.node(i);
        const TPoint2D shifted(r.midpoint.x + 0.8 * r.direction.x,
                               r.midpoint.y + 0.8 * r.direction.y);
        lines.push_back({c.midpoint, c.direction, shifted, r.direction, 1.0});
    }
    const TransformEstimate fl = rigidTransformFromLines(lines);
    ASSERT_TRUE(fl.valid);
    EXPECT_GT(fl.conditioning, 0.9) << "two perpendicular lines fix the translation";
    EXPECT_NEAR(fl.pose.x(), truth.x(), 1e-9);
    EXPECT_NEAR(fl.pose.y(), truth.y(), 1e-9);
    EXPECT_NEAR(mrpt::math::wrapToPi(fl.pose.phi() - truth.phi()), 0.0, 1e-12);

    // Parallel lines only: reported as degenerate.
    lines.pop_back();
    lines.push_back(lines.front());
    EXPECT_LT(rigidTransformFromLines(lines).conditioning, 1e-9);
}

TEST(SpgmSolver, RecoversTheIdentityMatchingOfIsomorphicGraphs) {
    const auto cur = someSegments();
    // Reference: the same walls moved, listed in another order.
    auto ref = transformed(cur, CPose2D(-3, 1, -1.0));
    const std::vector<std::size_t> perm = {3, 0, 4, 1, 2};  // ref[k] = moved cur[perm[k]]
    std::vector<toposlam::features::LineSegment> shuffled;
    for (std::size_t k : perm)
        shuffled.push_back(ref[k]);
    AttributedGraph gc, gr;
    gc.build(cur);
    gr.build(shuffled);
    std::vector<Assignment> candidates;
    for (std::uint32_t i = 0; i < gc.size(); ++i)
        for (std::uint32_t a = 0; a < gr.size(); ++a)
            candidates.push_back({i, a});
    Similarity sim;
    sim.build(gc, gr, candidates, {});
    SpgmSolver spgm;
    const std::vector<double>& p = spgm.solve(sim, candidates, gc.size(), gr.size());
    EXPECT_TRUE(spgm.converged()) << spgm.iterations() << " iterations";

    // Constraints of eq. 5 hold at the solution (to the projection tolerance).
    std::vector<double> rowSum(gc.size(), 0), colSum(gr.size(), 0);
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_GE(p[k], -1e-9);
        EXPECT_LE(p[k], 1 + 1e-9);
        rowSum[candidates[k].row] += p[k];
        colSum[candidates[k].col] += p[k];
    }
    for (double s : rowSum)
        EXPECT_NEAR(s, 1.0, 1e-4);
    for (double s : colSum)
        EXPECT_LE(s, 1.0 + 1e-4);

    GreedyAssignment greedy;
    const auto& pairs = greedy.solve(candidates, p, gc.size(), gr.size());
    ASSERT_EQ(pairs.size(), 5u);
    for (const AssignedPair& m : pairs)
        EXPECT_EQ(perm[m.col], m.row) << "row " << m.row;
}

TEST(AlignmentScorer, InliersViolationsAndOcclusion) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const CPose2D a(3, 3, 0.3), b(4, 2.5, -0.5);
    const auto sa = toposlam::test::simulateWithSegments(world, laser, a);
    const auto sb = toposlam::test::simulateWithSegments(world, laser, b);
    const CPose2D truth = b - a;  // pose of b's sensor in a's frame
    const AlignmentScore good = scoreAlignment(sa.polar, sb.polar, truth);
    EXPECT_EQ(good.violations, 0u);
    EXPECT_GT(good.inliers, sb.polar.validCount() * 8 / 10);
    // Exact points lie on the reference polyline (distance ~0) except a dozen next to
    // occluding edges, which are within the 0.1 m inlier distance of the occluder's edge.
    EXPECT_LT(good.inlierRms(), 0.02);
    const AlignmentScore bad = scoreAlignment(sa.polar, sb.polar, truth + CPose2D(0.4, 0, 0.2));
    EXPECT_GT(bad.violations, 20u);
    EXPECT_LT(bad.inlierFraction(), 0.5);
}

// A 180-degree laser turned round at the same place sees nothing the reference could have
// seen: those points are out of view (unverifiable, and counted apart for the overlap rule).
TEST(AlignmentScorer, CountsPointsOutsideTheReferenceView) {
    const auto world = toposlam::test::asymmetricRoom();
    const toposlam::simulation::LaserModel laser;  // 361 beams over 180 degrees
    const CPose2D a(3, 3, 0.3), b(3, 3, 0.3 + M_PI);
    const auto sa = toposlam::test::simulateWithSegments(world, laser, a);
    const auto sb = toposlam::test::simulateWithSegments(world, laser, b);
    const AlignmentScore same = scoreAlignment(sa.polar, sa.polar, CPose2D());
    EXPECT_EQ(same.outOfView, 0u);
    const AlignmentScore turned = scoreAlignment(sa.polar, sb.polar, b - a);
    EXPECT_LE(turned.outOfView, turned.unverifiable);
    // All but the beams at the edges of both fields of view (+-90 degrees) fall behind.
    EXPECT_GE(turned.outOfView + 4, sb.polar.validCount());
}

// Guess-free, from every segment pair: one of the candidates GraphScanMatcher refines is the
// true motion to within a vote cell (0.1 m) and the rotation bins' weighted mean (in a room
// of right angles a 90-degree turn of the truth may collect more votes; the refinement and
// scoring decide).
TEST(HoughPoseSearch, StrongCandidatesContainTheTrueMotion) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const CPose2D a(3, 2, 0.4);
    const std::vector<CPose2D> motions = {{0.8, -0.5, 0.7}, {-1.2, 1.5, -2.0}, {0.3, 0.2, 3.0}};
    const auto sa = toposlam::test::simulateWithSegments(world, laser, a);
    AttributedGraph ga, gb;
    ga.build(sa.features.segments);
    HoughPoseSearch hough;
    for (const CPose2D& motion : motions) {
        SCOPED_TRACE(motion.asString());
        const auto sb = toposlam::test::simulateWithSegments(world, laser, a + motion);
        gb.build(sb.features.segments);
        std::vector<ScoredAssignment> pairs;
        for (std::uint32_t i = 0; i < gb.size(); ++i)
            for (std::uint32_t j = 0; j < ga.size(); ++j)
                pairs.push_back({i, j, 0.0});
        const HoughPoseSearchOptions options;
        const auto& candidates = hough.search(sa.polar, sb.polar, gb, ga, pairs, options);
        std::size_t found = candidates.size();
        for (std::size_t k = 0; k < candidates.size() && found == candidates.size(); ++k) {
            const CPose2D& c = candidates[k].pose;
            if (std::hypot(c.x() - motion.x(), c.y() - motion.y()) < 0.1 &&
                std::abs(mrpt::math::wrapToPi(c.phi() - motion.phi())) < 0.02)
                found = k;
        }
        EXPECT_LT(found, GraphMatcherOptions().houghRefineTop);
        // Votes count current points, each at most once per cell: a 3x3 peak sum has at most
        // 9 votes per voting point (every stride-th beam).
        for (const PoseCandidate& c : candidates)
            EXPECT_LE(c.votes, 9.0 * double(sb.polar.size() / options.stride + 1));
    }
}

TEST(PolarScan, BeamLookupAndWrapAround) {
    PolarScan s;
    std::vector<float> r(360, 2.0f);
    std::vector<char> v(360, 1);
    s.assign(-M_PI, 2 * M_PI / 360, r, v, 10.0);
    EXPECT_TRUE(s.fullCircle());
    EXPECT_EQ(s.beamAt(-M_PI), 0);
    EXPECT_EQ(s.beamAt(M_PI - 0.1 * M_PI / 180), 0) << "wraps to the first beam";
    EXPECT_EQ(s.beamAt(0.0), 180);
    EXPECT_EQ(s.neighbour(0, -1), 359);

    PolarScan half;
    std::vector<float> r2(181, 2.0f);
    std::vector<char> v2(181, 1);
    half.assign(-M_PI / 2, M_PI / 180, r2, v2, 10.0);
    EXPECT_FALSE(half.fullCircle());
    EXPECT_EQ(half.beamAt(M_PI / 2), 180);
    EXPECT_EQ(half.beamAt(M_PI / 2 + 0.02), -1);
    EXPECT_EQ(half.beamAt(M_PI), -1);
    EXPECT_EQ(half.neighbour(180, 1), -1);
}
