#include <gtest/gtest.h>
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <cmath>

using namespace toposlam::evaluation;
using mrpt::math::TPose2D;
using toposlam::io::Trajectory2D;

namespace {

// Poses every 0.25 m along +x from 0 to 4 m (17 poses, stamps 0..16 s). Quarter metres are
// exact in binary, so the path lengths the scheme compares are exact too.
Trajectory2D straightLine() {
    Trajectory2D t;
    for (int i = 0; i <= 16; ++i)
        t.push_back({double(i), {0.25 * i, 0, 0}});
    return t;
}

}  // namespace

TEST(GroundTruthRelations, ConsecutivePlusDoublingSeparations) {
    const PoseRelations r = relationsFromGroundTruth(straightLine(), {true, 1.0});
    // 16 consecutive pairs; d = 1 m: starts at 0, 0.5, ..., 3.0 m (7); d = 2 m: starts at 0, 1,
    // 2 m (3); d = 4 m: start 0 (1); d = 8 m exceeds the 4 m path.
    ASSERT_EQ(r.size(), 16u + 7u + 3u + 1u);
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_EQ(r[i].stamp1, double(i));
        EXPECT_EQ(r[i].stamp2, double(i + 1));
        EXPECT_NEAR(r[i].motion.x, 0.25, 1e-15);
    }
    // First 1 m relation: pose 0 -> pose 4; second starts 0.5 m later, at pose 2.
    EXPECT_EQ(r[16].stamp1, 0.0);
    EXPECT_EQ(r[16].stamp2, 4.0);
    EXPECT_NEAR(r[16].motion.x, 1.0, 1e-15);
    EXPECT_EQ(r[17].stamp1, 2.0);
    EXPECT_EQ(r[22].stamp1, 12.0);  // the 7th 1 m relation starts at 3 m
    EXPECT_EQ(r[22].stamp2, 16.0);
    EXPECT_EQ(r[23].stamp2, 8.0);  // first 2 m relation
    EXPECT_EQ(r[26].stamp1, 0.0);  // the 4 m relation spans the whole path
    EXPECT_EQ(r[26].stamp2, 16.0);
    EXPECT_NEAR(r[26].motion.x, 4.0, 1e-15);
}

TEST(GroundTruthRelations, ReportsTheSeparationOfEachRelation) {
    std::vector<double> separations;
    const PoseRelations r = relationsFromGroundTruth(straightLine(), {true, 1.0}, &separations);
    ASSERT_EQ(separations.size(), r.size());
    EXPECT_EQ(separations[15], 0.0) << "consecutive";
    EXPECT_EQ(separations[16], 1.0);
    EXPECT_EQ(separations[22], 1.0);
    EXPECT_EQ(separations[23], 2.0);
    EXPECT_EQ(separations[26], 4.0);
}

TEST(GroundTruthRelations, OptionsSelectTheLevels) {
    EXPECT_EQ(relationsFromGroundTruth(straightLine(), {true, 0.0}).size(), 16u);
    EXPECT_EQ(relationsFromGroundTruth(straightLine(), {false, 1.0}).size(), 11u);
    EXPECT_EQ(relationsFromGroundTruth(straightLine(), {true, 5.0}).size(), 16u)
        << "separation longer than the path: only consecutive pairs";
    EXPECT_TRUE(relationsFromGroundTruth({}, {}).empty());
    EXPECT_TRUE(relationsFromGroundTruth({{1, {0, 0, 0}}}, {}).empty());
}

TEST(GroundTruthRelations, TurningInPlaceAddsNoPathLength) {
    // 1 m, a 90 deg turn in place, 1 m: path length 2 m; the 2 m relation goes around the corner.
    const Trajectory2D t = {
        {0, {0, 0, 0}}, {1, {1, 0, 0}}, {2, {1, 0, M_PI / 2}}, {3, {1, 1, M_PI / 2}}};
    const PoseRelations r = relationsFromGroundTruth(t, {false, 2.0});
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].stamp2, 3.0);
    EXPECT_NEAR(r[0].motion.x, 1.0, 1e-12);
    EXPECT_NEAR(r[0].motion.y, 1.0, 1e-12);
    EXPECT_NEAR(r[0].motion.phi, M_PI / 2, 1e-12);
}

TEST(GroundTruthRelations, ScoresTheTruthAndItsRigidCopyAsExact) {
    Trajectory2D truth;
    for (int i = 0; i < 200; ++i) {  // a spiral: turns and changing step lengths
        const double a = 0.05 * i;
        truth.push_back({100.0 + 0.1 * i, {a * std::cos(a), a * std::sin(a), a + M_PI / 2}});
    }
    const PoseRelations relations = relationsFromGroundTruth(truth);
    Trajectory2D moved = truth;
    for (auto& p : moved)
        p.pose = TPose2D(10, -3, -1.0) + p.pose;
    const RelativePoseErrorResult r = evaluateRelativePoseError(moved, relations);
    EXPECT_EQ(r.matchedRelations, relations.size());
    EXPECT_LT(r.translation.max, 1e-9);  // round-off of O(10 m) coordinates
    EXPECT_LT(r.rotation.max, 1e-9);
}

TEST(GroundTruthRelations, NonFiniteGroundTruthIsRejected) {
    const Trajectory2D t = {{0, {0, 0, 0}}, {1, {1, 0, std::nan("")}}};
    EXPECT_THROW(relationsFromGroundTruth(t), std::invalid_argument);
}
