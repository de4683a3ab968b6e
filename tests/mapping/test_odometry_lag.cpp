// OdometryLag: odometry that stalls while the robot moves, then catches up.
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/mapping/OdometryLag.h>

namespace toposlam::mapping {
namespace {

using mrpt::poses::CPose2D;

const CPose2D kStill(0, 0, 0);
const CPose2D kTurning(0.0, 0.0, mrpt::DEG2RAD(6.0));  // a turn on the spot, per scan

TEST(OdometryLag, AfterAStallAnIncrementFarFromTheLastMotionIsACatchUp) {
    OdometryLag lag;
    EXPECT_FALSE(lag.catchingUp(kTurning, kTurning));  // fresh odometry
    EXPECT_FALSE(lag.catchingUp(kStill, kTurning));    // stalled: the robot turned on
    EXPECT_FALSE(lag.catchingUp(kStill, kTurning));
    // Back, with the two scans of the stall in it: 18 deg where the robot turns 6.
    EXPECT_TRUE(lag.catchingUp(CPose2D(0, 0, mrpt::DEG2RAD(18.0)), kTurning));
    // Back in step with the registered motion: the odometry again.
    EXPECT_FALSE(lag.catchingUp(CPose2D(0, 0, mrpt::DEG2RAD(7.0)), kTurning));
}

TEST(OdometryLag, AStepShorterThanTheLastMotionIsNoCatchUp) {
    // A backlog adds motion; a robot slowing down reads less (at a low scan rate by much).
    OdometryLag lag;
    const CPose2D fastTurn(0.6, 0.0, mrpt::DEG2RAD(20.0));
    lag.catchingUp(kStill, fastTurn);  // stalled
    EXPECT_FALSE(lag.catchingUp(CPose2D(0.6, 0.0, mrpt::DEG2RAD(3.0)), fastTurn));
}

TEST(OdometryLag, AStandstillIsNoStall) {
    OdometryLag lag;
    EXPECT_FALSE(lag.catchingUp(kStill, kStill));  // standing: zero odometry, no registered motion
    EXPECT_FALSE(lag.catchingUp(kStill, CPose2D(0.005, 0.0, 0.001)));  // registration noise
    // Setting off into a fast turn departs from the last motion, but nothing stalled.
    EXPECT_FALSE(lag.catchingUp(CPose2D(0, 0, mrpt::DEG2RAD(20.0)), kStill));
}

TEST(OdometryLag, ARobotThatStopsIsNoStallOnceItHasStopped) {
    OdometryLag lag;
    EXPECT_FALSE(lag.catchingUp(kStill, kTurning));  // the first scan at rest looks like a stall
    EXPECT_FALSE(lag.catchingUp(kStill, kStill));    // ... but registration shows it stopped
    EXPECT_FALSE(lag.catchingUp(CPose2D(0, 0, mrpt::DEG2RAD(20.0)), kStill));
}

TEST(OdometryLag, CatchingUpEndsAfterAFewScans) {
    OdometryLag lag;
    lag.catchingUp(kStill, kTurning);
    const CPose2D fast(0, 0, mrpt::DEG2RAD(25.0));
    int catchUps = 0;
    for (int k = 0; k < 10; ++k)
        catchUps += lag.catchingUp(fast, kTurning);
    EXPECT_EQ(catchUps, OdometryLag::kMaxCatchUpScans);
}

}  // namespace
}  // namespace toposlam::mapping
