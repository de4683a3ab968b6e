// The laser's frame (LaserFrame.h): a robot's poses moved to the laser a log states for each
// scan fit relations made in the laser's frame exactly, while the robot's own poses are off by
// up to twice the mounting on turning relations; a log whose laser sits at the robot's centre
// changes nothing.
#include "FigureOfEight.h"

#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/LaserFrame.h>
#include <toposlam/evaluation/RelativePoseError.h>

using namespace toposlam::evaluation;
using toposlam::evaluation::test_paths::figureOfEight;
using toposlam::io::Trajectory2D;

namespace {

// One scan per pose of `path`, its laser at (x, y) on the robot.
Trajectory2D lasersAt(const Trajectory2D& path, double x, double y) {
    Trajectory2D lasers;
    for (const auto& p : path)
        lasers.push_back({p.stamp, {x, y, 0}});
    return lasers;
}

}  // namespace

TEST(LaserFrame, TheRobotsPosesMovedToTheLaserFitRelationsMadeThere) {
    const Trajectory2D robot = figureOfEight();
    // The laser 0.22 m ahead and 0.05 m left of the robot's centre (fr-clinic's is 0.22 m
    // ahead), composed with MRPT's own pose algebra as the reference.
    const mrpt::poses::CPose2D mount(0.22, 0.05, 0);
    Trajectory2D laser;
    for (const auto& p : robot)
        laser.push_back({p.stamp, (mrpt::poses::CPose2D(p.pose) + mount).asTPose()});
    const PoseRelations relations = relationsFromGroundTruth(laser, {});

    const Trajectory2D lasers = lasersAt(robot, 0.22, 0.05);
    EXPECT_TRUE(laserOffCentre(lasers));
    const Trajectory2D moved = inLaserFrame(robot, lasers, 1e-5);
    ASSERT_EQ(moved.size(), robot.size());
    for (std::size_t i = 0; i < robot.size(); ++i) {
        EXPECT_NEAR(moved[i].pose.x, laser[i].pose.x, 1e-12);
        EXPECT_NEAR(moved[i].pose.y, laser[i].pose.y, 1e-12);
        EXPECT_EQ(moved[i].pose.phi, robot[i].pose.phi);
        EXPECT_EQ(moved[i].stamp, robot[i].stamp);
    }
    EXPECT_LT(evaluateRelativePoseError(moved, relations).translation.max, 1e-9);
    // The robot's own poses are off on every turning relation, by up to 2 x 0.226 m.
    const RelativePoseErrorResult asGiven = evaluateRelativePoseError(robot, relations);
    EXPECT_GT(asGiven.translation.mean, 0.02);
    EXPECT_LT(asGiven.translation.max, 2 * std::hypot(0.22, 0.05) + 1e-9);
}

TEST(LaserFrame, APoseWithoutItsScanTakesTheTypicalLaserPosition) {
    const Trajectory2D robot = {{10.0, {1, 2, M_PI / 2}}, {11.0, {3, 4, 0}}};
    // Three scans; none at 11 s. The typical position is the median of each coordinate.
    const Trajectory2D lasers = {
        {9.0, {0.3, 0.0, 0}}, {10.0, {0.2, 0.1, 0}}, {12.0, {0.2, 0.0, 0}}};
    const auto typical = typicalLaserPosition(lasers);
    EXPECT_DOUBLE_EQ(typical.x, 0.2);
    EXPECT_DOUBLE_EQ(typical.y, 0.0);
    const Trajectory2D moved = inLaserFrame(robot, lasers, 1e-5);
    EXPECT_NEAR(moved[0].pose.x, 1 - 0.1, 1e-12);  // heading +y: ahead is +y, left is -x
    EXPECT_NEAR(moved[0].pose.y, 2 + 0.2, 1e-12);
    EXPECT_NEAR(moved[1].pose.x, 3 + 0.2, 1e-12);
    EXPECT_NEAR(moved[1].pose.y, 4.0, 1e-12);
}

TEST(LaserFrame, ALaserAtTheRobotsCentreChangesNothing) {
    const Trajectory2D robot = figureOfEight();
    const Trajectory2D lasers = lasersAt(robot, 0, 0);
    EXPECT_FALSE(laserOffCentre(lasers));
    EXPECT_FALSE(laserOffCentre({}));
    const Trajectory2D moved = inLaserFrame(robot, lasers, 1e-5);
    for (std::size_t i = 0; i < robot.size(); ++i) {
        EXPECT_EQ(moved[i].pose.x, robot[i].pose.x);
        EXPECT_EQ(moved[i].pose.y, robot[i].pose.y);
    }
    const auto none = typicalLaserPosition({});
    EXPECT_EQ(none.x, 0.0);
    EXPECT_EQ(none.y, 0.0);
}
