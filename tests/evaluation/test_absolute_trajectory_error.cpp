#include <gtest/gtest.h>
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/RigidAlignment2D.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace toposlam::evaluation;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;
using toposlam::io::Trajectory2D;

TEST(RigidAlignment2D, RecoversAnExactRigidTransform) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-20, 20);
    const TPose2D transform(3.5, -2.25, 2.7);
    std::vector<TPoint2D> source, target;
    for (int i = 0; i < 50; ++i) {
        const double y = coord(rng), x = coord(rng);  // one draw per statement
        source.emplace_back(x, y);
        target.push_back(transform + source.back());
    }
    const TPose2D found = alignRigid2D(source, target);
    // Closed form: only round-off of O(20 m) coordinates.
    EXPECT_NEAR(found.x, transform.x, 1e-12);
    EXPECT_NEAR(found.y, transform.y, 1e-12);
    EXPECT_NEAR(found.phi, transform.phi, 1e-13);
}

TEST(RigidAlignment2D, DegenerateInputs) {
    EXPECT_EQ(alignRigid2D({}, {}), TPose2D(0, 0, 0));
    const TPose2D one = alignRigid2D({{1, 2}}, {{4, 6}});
    EXPECT_EQ(one, TPose2D(3, 4, 0)) << "one point: a pure translation";
    EXPECT_THROW(alignRigid2D({{0, 0}}, {}), std::invalid_argument);
}

TEST(AbsoluteTrajectoryError, HandComputedResidual) {
    // Estimate segment (-1,-0.75)-(1,0.75) is 2.5 m long, the truth (-1,0)-(1,0) is 2 m: the
    // best rotation lays it along x (θ = -atan(0.75)), leaving 0.25 m at each end.
    const Trajectory2D estimate = {{1, {-1, -0.75, 0}}, {2, {1, 0.75, 0}}};
    const Trajectory2D truth = {{1, {-1, 0, 0}}, {2, {1, 0, -std::atan(0.75)}}};
    const AbsoluteTrajectoryErrorResult r = evaluateAbsoluteTrajectoryError(estimate, truth);
    EXPECT_EQ(r.matchedPoses, 2u);
    EXPECT_NEAR(r.alignment.phi, -std::atan(0.75), 1e-14);
    EXPECT_NEAR(r.position.rms, 0.25, 1e-14);
    EXPECT_NEAR(r.position.mean, 0.25, 1e-14);
    EXPECT_NEAR(r.position.max, 0.25, 1e-14);
    // Headings after alignment: pose 1 is off by atan(0.75) rad, pose 2 exact.
    EXPECT_NEAR(r.heading.max, mrpt::RAD2DEG(std::atan(0.75)), 1e-12);
    EXPECT_NEAR(r.heading.mean, mrpt::RAD2DEG(std::atan(0.75)) / 2, 1e-12);
}

TEST(AbsoluteTrajectoryError, RigidCopyHasZeroErrorAndUnmatchedPosesAreSkipped) {
    Trajectory2D truth, estimate;
    const TPose2D transform(-7, 1.5, -0.9);  // estimate frame -> truth frame
    for (int i = 0; i < 100; ++i) {
        const TPose2D p(0.1 * i, std::sin(0.1 * i), 0.02 * i);
        truth.push_back({double(i), p});
        estimate.push_back({double(i), (TPose2D(0, 0, 0) - transform) + p});
    }
    estimate.push_back({1000.0, {50, 50, 0}});  // no true pose at 1000 s: left out
    const AbsoluteTrajectoryErrorResult r = evaluateAbsoluteTrajectoryError(estimate, truth);
    EXPECT_EQ(r.estimatePoses, 101u);
    EXPECT_EQ(r.matchedPoses, 100u);
    EXPECT_NEAR(r.alignment.x, transform.x, 1e-12);
    EXPECT_NEAR(r.alignment.y, transform.y, 1e-12);
    EXPECT_NEAR(r.alignment.phi, transform.phi, 1e-12);
    EXPECT_LT(r.position.max, 1e-12);
    EXPECT_LT(r.heading.max, 1e-10);
}
