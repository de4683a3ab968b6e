// The one wording of where a laser sits on the robot, shared by toposlam-slam's summary and the
// SLAM benchmark's log lines.
#include <gtest/gtest.h>

#include <toposlam/io/LaserPosition.h>

namespace toposlam::io {
namespace {

TEST(LaserPosition, NamesEachSideInMillimetres) {
    EXPECT_EQ(describeLaserPosition({0.22, 0}),
              "0.220 m ahead and 0.000 m left of the robot's centre");
    EXPECT_EQ(describeLaserPosition({-0.2, -0.05}),
              "0.200 m behind and 0.050 m right of the robot's centre");
    EXPECT_EQ(describeLaserPosition({0.0004, 0.1234}),
              "0.000 m ahead and 0.123 m left of the robot's centre");
}

TEST(LaserPosition, OffCentreBeyondATenthOfAMillimetre) {
    EXPECT_FALSE(laserOffCentre({0, 0}));
    EXPECT_FALSE(laserOffCentre({6e-5, -6e-5}));  // 85 um: a mount stated to the millimetre
    EXPECT_TRUE(laserOffCentre({8e-5, 8e-5}));    // 113 um
    EXPECT_TRUE(laserOffCentre({-0.037, 0}));     // mit-csail's laser, behind its odometry's origin
}

}  // namespace
}  // namespace toposlam::io
