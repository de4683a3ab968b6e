#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace toposlam::evaluation;
using mrpt::DEG2RAD;
using mrpt::math::TPose2D;
using toposlam::io::Trajectory2D;

// Tolerance for values computed by hand: a few ulps of the O(1..1000) quantities involved.
constexpr double kExact = 1e-12;

TEST(RelativePoseError, IsInverseTrueMotionComposedWithEstimatedMotion) {
    // Robot facing +y moves 2 m forward: estimated motion δ_est = (2, 0, 0).
    const TPose2D from(1, 2, M_PI / 2), to(1, 4, M_PI / 2);
    const TPose2D truth(1.9, 0.1, 0.1);
    const TPose2D e = relativePoseError(from, to, truth);
    // δ_gt⁻¹ ⊕ δ_est = (R(-0.1)·(t_est - t_gt), θ_est - θ_gt), t_est - t_gt = (0.1, -0.1).
    EXPECT_NEAR(e.x, 0.1 * (std::cos(0.1) - std::sin(0.1)), kExact);
    EXPECT_NEAR(e.y, -0.1 * (std::sin(0.1) + std::cos(0.1)), kExact);
    EXPECT_NEAR(e.phi, -0.1, kExact);
}

TEST(RelativePoseError, ConventionIsTheBenchmarksNotCartographers) {
    // True motion 1 m straight; the estimate also moved 1 m straight but ended turned by 0.1 rad.
    // Benchmark (Kümmerle): e = δ_gt⁻¹ ⊕ δ_est = (0, 0, 0.1): no translational error.
    // Cartographer: δ_est ⊕ δ_gt⁻¹ = (1 - cos 0.1, -sin 0.1, 0.1): |t| = 2 sin 0.05 = 0.09996.
    const Trajectory2D estimate = {{1.0, {0, 0, 0}}, {2.0, {1, 0, 0.1}}};
    const PoseRelations relations = {{1.0, 2.0, {1, 0, 0}}};
    const RelativePoseErrorResult r = evaluateRelativePoseError(estimate, relations);
    ASSERT_EQ(r.matchedRelations, 1u);
    EXPECT_NEAR(r.translation.mean, 0.0, kExact);
    EXPECT_NEAR(r.rotation.mean, mrpt::RAD2DEG(0.1), kExact);
}

TEST(RelativePoseError, StatisticsOfKnownErrors) {
    // Poses 1 m apart on a line; all relations claim "no motion, turned by φ", so the errors are
    // exactly the estimated distances (1, 2, 3 m) and φ (10, 20, 30 deg).
    const Trajectory2D estimate = {
        {10, {0, 0, 0}}, {11, {1, 0, 0}}, {12, {2, 0, 0}}, {13, {3, 0, 0}}};
    const PoseRelations relations = {{10, 11, {0, 0, DEG2RAD(10.0)}},
                                     {11, 13, {0, 0, DEG2RAD(-20.0)}},
                                     {10, 13, {0, 0, DEG2RAD(30.0)}},
                                     {10, 14, {0, 0, 0}}};  // no pose at 14: unmatched
    const RelativePoseErrorResult r = evaluateRelativePoseError(estimate, relations);
    EXPECT_EQ(r.totalRelations, 4u);
    EXPECT_EQ(r.matchedRelations, 3u);
    EXPECT_EQ(r.unmatchedRelations(), 1u);
    ASSERT_EQ(r.errors.size(), 3u);
    EXPECT_EQ(r.errors[1].relation, 1u);
    EXPECT_EQ(r.errors[1].fromPose, 1u);
    EXPECT_EQ(r.errors[1].toPose, 3u);

    // {1, 2, 3}: mean 2, sample std 1, max 3, rms sqrt(14/3).
    EXPECT_NEAR(r.translation.mean, 2.0, kExact);
    EXPECT_NEAR(r.translation.std, 1.0, kExact);
    EXPECT_NEAR(r.translation.max, 3.0, kExact);
    EXPECT_NEAR(r.translation.rms, std::sqrt(14.0 / 3.0), kExact);
    // {10, 20, 30} deg.
    EXPECT_NEAR(r.rotation.mean, 20.0, 1e-10);
    EXPECT_NEAR(r.rotation.std, 10.0, 1e-10);
    EXPECT_NEAR(r.rotation.max, 30.0, 1e-10);
    // {1, 4, 9} m²: mean 14/3, std sqrt(((11/3)² + (2/3)² + (13/3)²) / 2) = sqrt(49/3).
    EXPECT_NEAR(r.translationSquared.mean, 14.0 / 3.0, kExact);
    EXPECT_NEAR(r.translationSquared.std, std::sqrt(49.0 / 3.0), kExact);
    EXPECT_NEAR(r.translationSquared.max, 9.0, kExact);
    // {100, 400, 900} deg²: mean 1400/3, std sqrt(((1100/3)² + (200/3)² + (1300/3)²) / 2).
    EXPECT_NEAR(r.rotationSquared.mean, 1400.0 / 3.0, 1e-8);
    EXPECT_NEAR(r.rotationSquared.std, std::sqrt(490000.0 / 3.0), 1e-8);
    EXPECT_NEAR(r.rotationSquared.max, 900.0, 1e-8);
}

TEST(RelativePoseError, InverseOrderRelationIsTheMotionFromT1ToT2) {
    // Relation (13 -> 10): motion from the pose at 13 back to the pose at 10, in the frame of
    // the pose at 13 (as 6 lines of intel.relations have it). Facing +x at (3,0), the pose at
    // (0,0) is 3 m behind: (-3, 0, 0). Swapping the stamps would give an error of 6 m.
    const Trajectory2D estimate = {{10, {0, 0, 0}}, {13, {3, 0, 0}}};
    const RelativePoseErrorResult r = evaluateRelativePoseError(estimate, {{13, 10, {-3, 0, 0}}});
    ASSERT_EQ(r.matchedRelations, 1u);
    EXPECT_NEAR(r.translation.mean, 0.0, kExact);
}

TEST(RelativePoseError, InvariantToARigidTransformOfTheWholeEstimate) {
    const Trajectory2D truth = {{1, {0, 0, 0}}, {2, {1, 0.2, 0.3}}, {3, {1.5, 1.0, 1.2}}};
    Trajectory2D moved = truth;
    const TPose2D transform(-4, 7, 2.5);
    for (auto& p : moved)
        p.pose = transform + p.pose;
    PoseRelations relations;
    for (std::size_t i = 0; i + 1 < truth.size(); ++i) {
        for (std::size_t j = i + 1; j < truth.size(); ++j) {
            relations.push_back({truth[i].stamp, truth[j].stamp, truth[j].pose - truth[i].pose});
        }
    }
    const RelativePoseErrorResult r = evaluateRelativePoseError(moved, relations);
    EXPECT_EQ(r.matchedRelations, 3u);
    EXPECT_NEAR(r.translation.max, 0.0, kExact);
    EXPECT_NEAR(r.rotation.max, 0.0, 1e-10);
}

TEST(RelativePoseError, RotationErrorIsWrapped) {
    // True turn +179 deg, estimated -179 deg: 2 deg apart, not 358.
    const Trajectory2D estimate = {{1, {0, 0, 0}}, {2, {0, 0, DEG2RAD(-179.0)}}};
    const auto r = evaluateRelativePoseError(estimate, {{1, 2, {0, 0, DEG2RAD(179.0)}}});
    EXPECT_NEAR(r.rotation.mean, 2.0, 1e-9);
}

TEST(StampedPoseLookup, MatchesWithinToleranceNearestFirst) {
    // mit-csail relations print stamps with 5 decimals, the log with 6: up to 5e-6 s apart.
    const Trajectory2D t = {{1134864645.903214, {0, 0, 0}},
                            {1134864645.20, {0, 0, 0}},  // out of order, like intel's stamps
                            {1134864646.324196, {0, 0, 0}},
                            {1134864646.324204, {0, 0, 0}}};
    const StampedPoseLookup lookup(t);
    EXPECT_EQ(lookup.find(1134864645.90321), std::optional<std::size_t>(0));
    EXPECT_EQ(lookup.find(1134864645.20), std::optional<std::size_t>(1));
    // Two candidates within the tolerance: the nearer one wins.
    EXPECT_EQ(lookup.find(1134864646.324203), std::optional<std::size_t>(3));
    EXPECT_EQ(lookup.find(1134864646.324197), std::optional<std::size_t>(2));
    EXPECT_FALSE(lookup.find(1134864645.903234)) << "2e-5 s off: beyond the 1e-5 s tolerance";
    EXPECT_FALSE(lookup.find(0.0));
    EXPECT_FALSE(lookup.find(2e9));
    const StampedPoseLookup loose(t, 1e-4);
    EXPECT_EQ(loose.find(1134864645.903234), std::optional<std::size_t>(0));
    EXPECT_FALSE(StampedPoseLookup({}).find(1.0)) << "empty trajectory";
}

TEST(RelativePoseError, NonFiniteTrajectoryIsRejected) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Trajectory2D estimate = {{1, {0, 0, 0}}, {2, {nan, 0, 0}}};
    EXPECT_THROW(evaluateRelativePoseError(estimate, {{1, 2, {1, 0, 0}}}), std::invalid_argument);
}

TEST(ErrorStatistics, EmptyAndSingleValue) {
    const ErrorStatistics none = summarizeErrors({});
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(none.mean, 0.0);
    const ErrorStatistics one = summarizeErrors({2.5});
    EXPECT_EQ(one.count, 1u);
    EXPECT_EQ(one.mean, 2.5);
    EXPECT_EQ(one.std, 0.0) << "sample std of one value is defined as 0";
    EXPECT_EQ(one.max, 2.5);
}
