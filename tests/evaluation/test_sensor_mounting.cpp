// The sensor mounting estimated from odometry and a trajectory of sensor poses: exact on exact
// data, within its own standard deviations on noisy data, and no answer from a straight drive.
#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/evaluation/SensorMounting.h>

#include <cmath>
#include <random>

namespace {

using toposlam::evaluation::estimateSensorMounting;
using toposlam::io::Trajectory2D;

struct Logs {
    Trajectory2D odometry, sensor;
};

/// A robot driving 0.1 m per step while turning by turnPerStep(i) rad; its odometry measures
/// `scale` times the distances, the sensor sits at `mounting` on it; `noise` (m, rad) on the
/// sensor poses.
template <typename Turn>
Logs drive(const mrpt::poses::CPose2D& mounting, double scale, double noise, Turn turnPerStep) {
    Logs out;
    mrpt::poses::CPose2D robot, odometry;
    std::mt19937 rng(7);
    std::normal_distribution<double> n(0, noise > 0 ? noise : 1);
    for (int i = 0; i < 2000; ++i) {
        const double stamp = 0.1 * i;
        out.odometry.push_back({stamp, odometry.asTPose()});
        mrpt::poses::CPose2D sensor = robot + mounting;
        if (noise > 0) {
            const double phi = 0.1 * n(rng), y = n(rng), x = n(rng);  // one draw per statement
            sensor = sensor + mrpt::poses::CPose2D(x, y, phi);
        }
        out.sensor.push_back({stamp, sensor.asTPose()});
        const double turn = turnPerStep(i);
        robot = robot + mrpt::poses::CPose2D(0.1, 0, turn);
        odometry = odometry + mrpt::poses::CPose2D(0.1 * scale, 0, turn);
    }
    return out;
}

double weave(int i) {
    return 0.08 * std::sin(0.02 * i);
}

TEST(SensorMounting, RecoversTheMountingAndTheOdometryScaleFromExactData) {
    const mrpt::poses::CPose2D mounting(0.25, -0.04, 5.0 * M_PI / 180);
    const Logs logs = drive(mounting, 1.03, 0, weave);
    const auto m = estimateSensorMounting(logs.odometry, logs.sensor, 1e-6);
    ASSERT_TRUE(m);
    EXPECT_NEAR(m->mounting.x, 0.25, 1e-9);
    EXPECT_NEAR(m->mounting.y, -0.04, 1e-9);
    EXPECT_NEAR(m->mounting.phi, 5.0 * M_PI / 180, 1e-9);
    EXPECT_NEAR(m->odometryScale, 1.03, 1e-9);
    EXPECT_GT(m->pairs, 100u);
}

TEST(SensorMounting, TheOdometryItselfSitsAtTheRobotsOrigin) {
    const Logs logs = drive(mrpt::poses::CPose2D(), 1.0, 0, weave);
    const auto m = estimateSensorMounting(logs.odometry, logs.odometry, 1e-6);
    ASSERT_TRUE(m);
    EXPECT_NEAR(m->mounting.x, 0, 1e-9);
    EXPECT_NEAR(m->mounting.y, 0, 1e-9);
    EXPECT_NEAR(m->mounting.phi, 0, 1e-9);
    EXPECT_NEAR(m->odometryScale, 1, 1e-9);
}

TEST(SensorMounting, NoisyPosesGiveTheMountingWithinItsStandardDeviations) {
    // 1 cm and 0.06 deg of noise on every sensor pose, as a good SLAM result has.
    const mrpt::poses::CPose2D mounting(-0.035, 0.02, 0);
    const Logs logs = drive(mounting, 0.98, 0.01, weave);
    const auto m = estimateSensorMounting(logs.odometry, logs.sensor, 1e-6);
    ASSERT_TRUE(m);
    EXPECT_GT(m->stdX, 0);
    EXPECT_LT(m->stdX, 0.01);
    EXPECT_NEAR(m->mounting.x, -0.035, 4 * m->stdX);
    EXPECT_NEAR(m->mounting.y, 0.02, 4 * m->stdY);
    EXPECT_NEAR(m->odometryScale, 0.98, 0.01);
}

TEST(SensorMounting, AStraightDriveSaysNothingAboutTheMounting) {
    const Logs logs = drive(mrpt::poses::CPose2D(0.2, 0, 0), 1.0, 0, [](int) { return 0.0; });
    EXPECT_FALSE(estimateSensorMounting(logs.odometry, logs.sensor, 1e-6));
}

TEST(SensorMounting, PosesArePairedByStamp) {
    // The trajectory has every other pose only, and stamps the odometry does not have are
    // skipped: the answer stays exact.
    const mrpt::poses::CPose2D mounting(0.1, 0.05, -0.1);
    Logs logs = drive(mounting, 1.0, 0, weave);
    Trajectory2D sparse;
    for (std::size_t i = 0; i < logs.sensor.size(); i += 2)
        sparse.push_back(logs.sensor[i]);
    sparse.push_back({1e6, {}});
    const auto m = estimateSensorMounting(logs.odometry, sparse, 1e-6);
    ASSERT_TRUE(m);
    EXPECT_NEAR(m->mounting.x, 0.1, 1e-9);
    EXPECT_NEAR(m->mounting.y, 0.05, 1e-9);
}

}  // namespace
