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

TEST(OdometryLag, TheReadingAfterAStallRegistrationSawNothingOfIsTheStep) {
    // Down a corridor: the odometry repeats its reading for two scans and registration, with
    // nothing to fix the motion along it, keeps them where the stall left them (turned by ICP's
    // noise, a degree).
    OdometryLag lag;
    const CPose2D ahead(0.3, 0.0, 0.0), jitter(0.004, -0.002, mrpt::DEG2RAD(1.2));
    lag.registered(ahead, ahead);  // fresh odometry, the robot moving
    EXPECT_FALSE(lag.bridges(ahead, ahead));
    lag.registered(kStill, jitter);
    lag.registered(kStill, kStill);
    EXPECT_EQ(lag.repeatedScans(), 2);
    EXPECT_FALSE(lag.bridges(kStill, kStill));
    // The reading after: the three steps since the last fresh one.
    const CPose2D reading = ahead + ahead + ahead;
    // Not a robot that stopped and set off again: more than a step.
    EXPECT_FALSE(lag.bridges(CPose2D(0.05, 0, 0), kStill));
    ASSERT_TRUE(lag.bridges(reading, kStill));
    const CPose2D step = lag.stepSinceStall(reading);
    const CPose2D expected = (-jitter) + reading;  // from where the stall's scans were put
    EXPECT_NEAR(step.x(), expected.x(), 1e-12);
    EXPECT_NEAR(step.y(), expected.y(), 1e-12);
    EXPECT_NEAR(step.phi(), expected.phi(), 1e-12);
    lag.registered(reading, step);
    EXPECT_EQ(lag.repeatedScans(), 0);
    EXPECT_FALSE(lag.bridges(ahead, step));
}

TEST(OdometryLag, ACatchUpBeyondWhatRegistrationSawAlongAStraightStretchIsBridged) {
    const CPose2D ahead(0.3, 0.0, 0.0), part(0.1, 0.002, mrpt::DEG2RAD(0.5));
    const CPose2D reading = ahead + ahead + ahead;  // the stall's two scans and this one
    OdometryLag partly;  // ICP went part of the way along the corridor, then kept still
    partly.registered(ahead, ahead);
    partly.registered(kStill, part);
    partly.registered(kStill, kStill);
    ASSERT_TRUE(partly.bridges(reading, kStill));
    EXPECT_TRUE(partly.stallScansBehind(reading));  // 0.1 m where the reading has 0.6
    const CPose2D step = partly.stepSinceStall(reading);
    EXPECT_NEAR(step.x(), ((-part) + reading).x(), 1e-12);
    OdometryLag followed;  // registration saw the stall's motion: its scans are where they were
    followed.registered(ahead, ahead);
    followed.registered(kStill, ahead);
    followed.registered(kStill, ahead);
    ASSERT_TRUE(followed.bridges(reading, ahead));  // the step left: one more
    EXPECT_NEAR(followed.stepSinceStall(reading).x(), 0.3, 1e-12);
    EXPECT_FALSE(followed.stallScansBehind(reading));
}

TEST(OdometryLag, AStallRegistrationSawTheRobotTurnInOrAStandstillIsNotBridged) {
    // A turn shows walls across, so registration saw it; there it is the reading that may fall
    // short of the stall (mit-csail: 7.6 deg where the robot turned 25), and the last motion
    // predicts.
    const CPose2D ahead(0.3, 0.0, 0.0), turning(0.1, 0.0, mrpt::DEG2RAD(15.0));
    OdometryLag seen;
    seen.registered(ahead, ahead);
    seen.registered(kStill, turning);
    EXPECT_FALSE(seen.bridges(ahead + turning + turning, turning));
    OdometryLag standing;  // the robot stood still: the odometry rightly read nothing
    standing.registered(kStill, kStill);
    standing.registered(kStill, kStill);
    EXPECT_FALSE(standing.bridges(ahead, kStill));
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
