#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <toposlam/simulation/OdometryModel.h>

#include <cmath>
#include <vector>

using mrpt::poses::CPose2D;
using namespace toposlam::simulation;

namespace {

struct Stats {
    double mean = 0, std = 0;
};
Stats stats(const std::vector<double>& v) {
    Stats s;
    for (double x : v)
        s.mean += x;
    s.mean /= static_cast<double>(v.size());
    for (double x : v)
        s.std += (x - s.mean) * (x - s.mean);
    s.std = std::sqrt(s.std / static_cast<double>(v.size() - 1));
    return s;
}

constexpr int kTrials = 4000;
// Sampling tolerances at 4 standard errors: mean: 4 sigma / sqrt(N); std: relative
// 4 / sqrt(2 (N - 1)) (Gaussian samples).
double meanTolerance(double sigma) {
    return 4 * sigma / std::sqrt(double(kTrials));
}
const double kStdRelTolerance = 4 / std::sqrt(2.0 * (kTrials - 1));

OdometryErrorModel noErrorsBut() {
    return OdometryErrorModel::exact();
}

/// Drives `distance` m straight ahead in `steps` steps; returns the final odometry.
CPose2D driveStraight(OdometryModel& odo, double distance, int steps, std::mt19937& rng) {
    for (int k = 0; k < steps; ++k)
        odo.move(CPose2D(distance / steps, 0, 0), rng);
    return odo.pose();
}

}  // namespace

TEST(OdometryModel, ExactModelReproducesTheTrueMotion) {
    OdometryModel odo(OdometryErrorModel::exact(), CPose2D(1, 2, 0.3));
    CPose2D truth(1, 2, 0.3);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    for (int k = 0; k < 500; ++k) {
        // One draw per statement; includes sideways and backwards motion.
        const double phi = u(rng), y = u(rng), x = u(rng);
        const CPose2D inc(x, y, phi);
        truth = truth + inc;
        odo.move(inc, rng);
    }
    EXPECT_NEAR(odo.pose().x(), truth.x(), 1e-9);
    EXPECT_NEAR(odo.pose().y(), truth.y(), 1e-9);
    EXPECT_NEAR(std::remainder(odo.pose().phi() - truth.phi(), 2 * M_PI), 0.0, 1e-9);
}

TEST(OdometryModel, DistanceScaleAndTranslationNoise) {
    OdometryErrorModel m = noErrorsBut();
    m.distanceScale = 1.02;
    m.alpha3 = 4e-4;  // m^2 per m: std 6.3 cm after 10 m
    std::mt19937 rng(11);
    std::vector<double> x, yaw;
    for (int t = 0; t < kTrials; ++t) {
        OdometryModel odo(m);
        const CPose2D end = driveStraight(odo, 10.0, 100, rng);
        x.push_back(end.x());
        yaw.push_back(end.phi());
    }
    const double sigma = std::sqrt(m.alpha3 * 10);
    EXPECT_NEAR(stats(x).mean, 10.2, meanTolerance(sigma));
    EXPECT_NEAR(stats(x).std / sigma, 1.0, kStdRelTolerance);
    EXPECT_EQ(stats(yaw).std, 0.0) << "no rotation error was configured";
}

TEST(OdometryModel, CurvatureBiasAndHeadingNoiseFromDriving) {
    OdometryErrorModel m = noErrorsBut();
    m.curvaturePerMetre = 0.01;  // rad per m
    m.alpha2 = 1e-4;             // rad^2 per m
    std::mt19937 rng(12);
    std::vector<double> yaw;
    for (int t = 0; t < kTrials; ++t) {
        OdometryModel odo(m);
        yaw.push_back(driveStraight(odo, 10.0, 100, rng).phi());
    }
    const double sigma = std::sqrt(m.alpha2 * 10);
    EXPECT_NEAR(stats(yaw).mean, 0.1, meanTolerance(sigma));
    EXPECT_NEAR(stats(yaw).std / sigma, 1.0, kStdRelTolerance);
}

TEST(OdometryModel, RotationScaleAndNoiseWhenTurningOnTheSpot) {
    OdometryErrorModel m = noErrorsBut();
    m.rotationScale = 1.02;
    m.alpha1 = 1e-3;  // rad^2 per rad
    std::mt19937 rng(13);
    std::vector<double> turned;
    for (int t = 0; t < kTrials; ++t) {
        OdometryModel odo(m);
        double sum = 0;  // unwrapped: sum of the measured increments
        for (int k = 0; k < 36; ++k)
            sum += odo.measureIncrement(CPose2D(0, 0, M_PI / 18), rng).phi();
        turned.push_back(sum);
    }
    const double sigma = std::sqrt(m.alpha1 * 2 * M_PI);
    EXPECT_NEAR(stats(turned).mean, 1.02 * 2 * M_PI, meanTolerance(sigma));
    EXPECT_NEAR(stats(turned).std / sigma, 1.0, kStdRelTolerance);
}

TEST(OdometryModel, AStepOfMillimetresOffTheHeadingTurnsOnlyAsMuchAsTheRobot) {
    // Turning on the spot while the path drifts sideways by 3 mm per 2 degree step (a twitch
    // between two close stops): the heading error is that of the 72 degrees turned, not of the
    // 90 degrees sideways and back that a rot1 / rot2 decomposition would see in each step.
    OdometryErrorModel m = noErrorsBut();
    m.alpha1 = 1e-3;  // rad^2 per rad
    std::mt19937 rng(15);
    std::vector<double> turned;
    const double step = M_PI / 90;
    for (int t = 0; t < kTrials; ++t) {
        OdometryModel odo(m);
        double sum = 0;
        for (int k = 0; k < 36; ++k)
            sum += odo.measureIncrement(CPose2D(0, 0.003, step), rng).phi();
        turned.push_back(sum);
    }
    const double sigma = std::sqrt(m.alpha1 * 36 * step);
    EXPECT_NEAR(stats(turned).mean, 36 * step, meanTolerance(sigma));
    EXPECT_NEAR(stats(turned).std / sigma, 1.0, kStdRelTolerance);
}

TEST(OdometryModel, DriftDoesNotDependOnTheOdometryRate) {
    // Linear variances: 10 coarse steps and 1000 fine steps drift alike.
    OdometryErrorModel m = noErrorsBut();
    m.alpha3 = 4e-4;
    m.alpha2 = 1e-4;
    std::mt19937 rng(14);
    for (int steps : {10, 1000}) {
        std::vector<double> x, yaw;
        for (int t = 0; t < kTrials / 4; ++t) {
            OdometryModel odo(m);
            const CPose2D end = driveStraight(odo, 10.0, steps, rng);
            x.push_back(end.x());
            yaw.push_back(end.phi());
        }
        const double tol = 4 / std::sqrt(2.0 * (kTrials / 4 - 1));
        EXPECT_NEAR(stats(yaw).std / std::sqrt(m.alpha2 * 10), 1.0, tol) << steps << " steps";
        // x also loses a little to the heading wander (second order, < 0.1 % here).
        EXPECT_NEAR(stats(x).std / std::sqrt(m.alpha3 * 10), 1.0, tol) << steps << " steps";
    }
}

TEST(OdometryModel, DefaultsDriftLikeARealRobot) {
    // 20 m square loop (four 5 m sides, four 90 deg turns) with the default model: the end
    // point is off by centimetres to decimetres and the heading by a few degrees, like real
    // wheel odometry, neither perfect nor useless.
    std::mt19937 rng(15);
    std::vector<double> posErr, yawErr;
    for (int t = 0; t < 500; ++t) {
        OdometryModel odo{OdometryErrorModel()};
        for (int side = 0; side < 4; ++side) {
            driveStraight(odo, 5.0, 50, rng);
            for (int k = 0; k < 9; ++k)
                odo.move(CPose2D(0, 0, M_PI / 18), rng);
        }
        posErr.push_back(std::hypot(odo.pose().x(), odo.pose().y()));
        yawErr.push_back(std::abs(odo.pose().phi()));
    }
    const double meanPos = stats(posErr).mean, meanYawDeg = stats(yawErr).mean * 180 / M_PI;
    EXPECT_GT(meanPos, 0.05);
    EXPECT_LT(meanPos, 1.0);
    EXPECT_GT(meanYawDeg, 1.0);
    EXPECT_LT(meanYawDeg, 15.0);
}

TEST(OdometryModel, LoadsTheConfigFileKeys) {
    mrpt::config::CConfigFileMemory ini;
    ini.write("Odometry", "distance_scale", 1.03);
    ini.write("Odometry", "rotation_scale", 0.98);
    ini.write("Odometry", "curvature_deg_per_m", 0.5);
    ini.write("Odometry", "rot_std_deg_per_sqrt_rad", 2.0);
    ini.write("Odometry", "rot_std_deg_per_sqrt_m", 1.0);
    ini.write("Odometry", "trans_std_m_per_sqrt_m", 0.02);
    ini.write("Odometry", "trans_std_m_per_sqrt_rad", 0.01);
    OdometryErrorModel m;
    m.loadFromConfigFile(ini, "Odometry");
    EXPECT_DOUBLE_EQ(m.distanceScale, 1.03);
    EXPECT_DOUBLE_EQ(m.rotationScale, 0.98);
    EXPECT_NEAR(m.curvaturePerMetre, 0.5 * M_PI / 180, 1e-15);
    EXPECT_NEAR(m.alpha1, std::pow(2.0 * M_PI / 180, 2), 1e-15);
    EXPECT_NEAR(m.alpha2, std::pow(1.0 * M_PI / 180, 2), 1e-15);
    EXPECT_NEAR(m.alpha3, 4e-4, 1e-15);
    EXPECT_NEAR(m.alpha4, 1e-4, 1e-15);
}
