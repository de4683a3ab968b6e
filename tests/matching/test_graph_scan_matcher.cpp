// The whole matcher on noise-free synthetic scans whose segments come from the world's
// geometry (SyntheticScans.h): exact recovery, ambiguity, feature-poor scans, order
// independence, guided matching.
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "SyntheticScans.h"

using mrpt::poses::CPose2D;
using namespace toposlam::matching;
using toposlam::test::simulateWithSegments;
using toposlam::test::SyntheticScan;

namespace {
double angleError(const CPose2D& a, const CPose2D& b) {
    return std::abs(mrpt::math::wrapToPi(a.phi() - b.phi()));
}
double translationError(const CPose2D& a, const CPose2D& b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}
}  // namespace

// Noise-free scans and exact segment lines. The paper's pipeline (segment-mode ICP on the
// matched lines) recovers the pose up to the ICP's step tolerances (1e-4 m, 1e-5 rad); the
// default pipeline's last polish fits local lines to the reference points, which are a
// fraction of a millimetre off next to corners, so it is held to 1 mm / 1 mrad.
TEST(GraphScanMatcher, RecoversKnownTransformsWithoutGuess) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const CPose2D reference(3.0, 2.0, 0.4);
    const SyntheticScan ref = simulateWithSegments(world, laser, reference);
    GraphScanMatcher paper, polished;
    paper.options().scanRefinement = false;
    const std::vector<CPose2D> motions = {{0.05, 0.0, 0.0}, {0.15, -0.1, 0.3}, {0.5, 0.3, -1.2},
                                          {1.0, 0.4, 3.1},  {-0.7, 1.2, 1.6},  {1.5, 2.5, -2.4}};
    for (const CPose2D& motion : motions) {
        const SyntheticScan cur = simulateWithSegments(world, laser, reference + motion);
        SCOPED_TRACE(motion.asString());
        for (GraphScanMatcher* m : {&paper, &polished}) {
            const MatchResult& r = m->match(ref.polar, ref.features, cur.polar, cur.features);
            const double tolerance = m == &paper ? 1e-4 : 1e-3;
            EXPECT_EQ(r.status, MatchStatus::Matched) << toString(r.status);
            EXPECT_LT(translationError(r.pose, motion), tolerance);
            EXPECT_LT(angleError(r.pose, motion), tolerance);
            EXPECT_GT(r.score.inlierFraction(), 0.99);
            EXPECT_GE(r.matches.size(), 4u);
        }
    }
}

// min_inliers is a count of beams 0.5 deg apart: a coarser laser puts fewer readings on the
// same walls and needs as many as cover the same bearing. The same pair seen with 0.5 deg
// and with 2 deg between beams, min_inliers set to 80 % of what the fine laser puts on the
// walls: both are matched. Counted as it is, the coarse scans (a quarter of the readings)
// fall short.
TEST(GraphScanMatcher, TheInlierFloorCoversTheSameBearingWhateverTheBeamSpacing) {
    const auto world = toposlam::test::asymmetricRoom();
    const CPose2D reference(3.0, 2.0, 0.4), motion(0.4, -0.2, 0.3);
    const auto matchWith = [&](std::size_t beams, std::size_t minInliers, double step) {
        const auto laser = toposlam::test::fullCircleLaser(beams);
        const SyntheticScan ref = simulateWithSegments(world, laser, reference);
        const SyntheticScan cur = simulateWithSegments(world, laser, reference + motion, 2);
        GraphScanMatcher matcher;
        matcher.options().minInliers = minInliers;
        matcher.options().minInliersBearingStep = step;
        return matcher.match(ref.polar, ref.features, cur.polar, cur.features);
    };
    const double halfDegree = 0.5 * M_PI / 180;
    const MatchResult fine = matchWith(720, 1, halfDegree);
    ASSERT_EQ(fine.status, MatchStatus::Matched) << toString(fine.status);
    const std::size_t floor = fine.score.inliers * 4 / 5;
    EXPECT_EQ(matchWith(720, floor, halfDegree).status, MatchStatus::Matched);
    const MatchResult coarse = matchWith(180, floor, halfDegree);
    EXPECT_EQ(coarse.status, MatchStatus::Matched) << toString(coarse.status);
    EXPECT_LT(translationError(coarse.pose, motion), 0.01);
    EXPECT_LT(coarse.score.inliers, floor);
    EXPECT_EQ(matchWith(180, floor, 0).status, MatchStatus::PoorFit);
}

TEST(GraphScanMatcher, CovarianceIsSmallAndPositive) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const SyntheticScan a = simulateWithSegments(world, laser, CPose2D(3, 2, 0));
    const SyntheticScan b = simulateWithSegments(world, laser, CPose2D(3.3, 2.2, 0.2));
    GraphScanMatcher matcher;
    const MatchResult& r = matcher.match(a.polar, a.features, b.polar, b.features);
    ASSERT_TRUE(r.reliable());
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(r.covariance(k, k), 0.0);
        EXPECT_LT(r.covariance(k, k), 1e-3);  // std < 3 cm / 1.8 deg with dozens of points
    }
}

// A square room seen from its centre by a 360-degree laser looks the same after any
// multiple of 90 degrees: four poses explain the scan perfectly, none may be reported.
TEST(GraphScanMatcher, SymmetricRoomIsAmbiguous) {
    toposlam::simulation::PolygonWorld square;
    square.addPolygon({{-3, -3}, {3, -3}, {3, 3}, {-3, 3}});
    const auto laser = toposlam::test::fullCircleLaser();
    const SyntheticScan a = simulateWithSegments(square, laser, CPose2D(0, 0, 0));
    const SyntheticScan b = simulateWithSegments(square, laser, CPose2D(0, 0, 0.5));
    GraphScanMatcher matcher;
    const MatchResult& r = matcher.match(a.polar, a.features, b.polar, b.features);
    EXPECT_EQ(r.status, MatchStatus::Ambiguous) << toString(r.status);
    EXPECT_FALSE(r.reliable());
    ASSERT_TRUE(r.alternative.has_value());
    EXPECT_GT(r.ambiguity, 0.9);
    // Both poses are rotations by 0.5 + k pi/2 about the centre.
    for (const CPose2D& p : {r.pose, *r.alternative}) {
        const double k = (p.phi() - 0.5) / (M_PI / 2);
        EXPECT_NEAR(k, std::round(k), 1e-3);
        EXPECT_LT(std::hypot(p.x(), p.y()), 1e-3);
    }
}

TEST(GraphScanMatcher, EmptyAndSingleWallScansGiveNoMatch) {
    const auto laser = toposlam::test::fullCircleLaser();
    toposlam::simulation::PolygonWorld nothing;
    toposlam::simulation::PolygonWorld wall;
    wall.addSegment({-5, 2}, {5, 2});
    const SyntheticScan empty = simulateWithSegments(nothing, laser, CPose2D(0, 0, 0));
    const SyntheticScan w1 = simulateWithSegments(wall, laser, CPose2D(0, 0, 0));
    const SyntheticScan w2 = simulateWithSegments(wall, laser, CPose2D(0.5, 0.2, 0.1));
    ASSERT_EQ(w1.features.segments.size(), 1u);
    GraphScanMatcher matcher;
    EXPECT_EQ(matcher.match(empty.polar, empty.features, empty.polar, empty.features).status,
              MatchStatus::TooFewFeatures);
    // One wall fixes no position along itself: the fallback's point search finds poses all
    // along it, and the refinement reports the free direction.
    const MatchStatus oneWall = matcher.match(w1.polar, w1.features, w2.polar, w2.features).status;
    EXPECT_TRUE(oneWall == MatchStatus::TooFewFeatures || oneWall == MatchStatus::Degenerate)
        << toString(oneWall);
    EXPECT_FALSE(matcher.match(w1.polar, w1.features, empty.polar, empty.features).reliable());

    // Two parallel walls (an endless corridor) fix no along-corridor position.
    toposlam::simulation::PolygonWorld corridor;
    corridor.addSegment({-30, 1}, {30, 1});
    corridor.addSegment({-30, -1.2}, {30, -1.2});
    const SyntheticScan c1 = simulateWithSegments(corridor, laser, CPose2D(0, 0, 0));
    const SyntheticScan c2 = simulateWithSegments(corridor, laser, CPose2D(0.6, 0.1, 0.05));
    const MatchResult& r = matcher.match(c1.polar, c1.features, c2.polar, c2.features);
    EXPECT_FALSE(r.reliable()) << toString(r.status);
}

TEST(GraphScanMatcher, ResultDoesNotDependOnSegmentOrder) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const SyntheticScan a = simulateWithSegments(world, laser, CPose2D(2.5, 3.0, 1.0));
    const SyntheticScan b = simulateWithSegments(world, laser, CPose2D(3.4, 2.6, -0.8));
    GraphScanMatcher matcher;
    const MatchResult first = matcher.match(a.polar, a.features, b.polar, b.features);
    ASSERT_TRUE(first.reliable());
    std::mt19937 rng(3);
    for (int trial = 0; trial < 5; ++trial) {
        auto fa = a.features, fb = b.features;
        std::shuffle(fa.segments.begin(), fa.segments.end(), rng);
        std::shuffle(fb.segments.begin(), fb.segments.end(), rng);
        const MatchResult& r = matcher.match(a.polar, fa, b.polar, fb);
        EXPECT_EQ(r.status, first.status);
        // Same pose up to floating-point summation order.
        EXPECT_LT(translationError(r.pose, first.pose), 1e-9);
        EXPECT_LT(angleError(r.pose, first.pose), 1e-9);
        EXPECT_EQ(r.matches.size(), first.matches.size());
    }
}

// With an odometry-like guess 1 m and 30 deg off, the guided matcher still finds the pose.
TEST(GraphScanMatcher, GuidedMatchingToleratesAPoorGuess) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto laser = toposlam::test::fullCircleLaser();
    const CPose2D reference(4.0, 2.0, 0.0), motion(0.8, 0.5, 0.6);
    const SyntheticScan a = simulateWithSegments(world, laser, reference);
    const SyntheticScan b = simulateWithSegments(world, laser, reference + motion);
    GraphScanMatcher matcher;
    const CPose2D guess = motion + CPose2D(0.7, -0.7, -30.0 * M_PI / 180);
    const MatchResult& r = matcher.match(a.polar, a.features, b.polar, b.features, guess);
    EXPECT_EQ(r.status, MatchStatus::Matched) << toString(r.status);
    EXPECT_LT(translationError(r.pose, motion), 1e-3);  // as in RecoversKnownTransforms...
    EXPECT_LT(angleError(r.pose, motion), 1e-3);
}
