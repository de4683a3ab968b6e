// OdometryCalibration: the odometry's distance scale from registered motion, only from scans
// registration fixed in every direction, applied once there is enough of it, and bounded.
#include <gtest/gtest.h>
#include <toposlam/mapping/OdometryCalibration.h>

#include <cmath>
#include <random>

using mrpt::poses::CPose2D;
using toposlam::mapping::OdometryCalibration;

namespace {

/// The calibration on, with its other settings as shipped.
OdometryCalibration::Options on() {
    OdometryCalibration::Options o;
    o.enabled = true;
    return o;
}

/// ICP's covariance of a scan fixed in every direction: 2 mm position, 0.1 deg heading.
mrpt::math::CMatrixDouble33 wellDetermined() {
    mrpt::math::CMatrixDouble33 c;
    c.setZero();
    c(0, 0) = c(1, 1) = 0.002 * 0.002;
    c(2, 2) = std::pow(0.1 * M_PI / 180, 2);
    return c;
}

/// ... and of a scan in a corridor along x: 5 cm along it, 2 mm across.
mrpt::math::CMatrixDouble33 corridorAlongX() {
    mrpt::math::CMatrixDouble33 c = wellDetermined();
    c(0, 0) = 0.05 * 0.05;
    return c;
}

/// Feeds `metres` of driving in 0.1 m steps (turning a little) whose odometry reads
/// `odometryScale` times the true distance, registered to the truth plus 2 mm noise.
void drive(OdometryCalibration& calibration, double metres, double odometryScale, std::mt19937& rng,
           const mrpt::math::CMatrixDouble33& covariance = wellDetermined()) {
    std::normal_distribution<double> noise(0.0, 0.002);
    std::uniform_real_distribution<double> turn(-0.1, 0.1);
    for (double d = 0; d < metres; d += 0.1) {
        const CPose2D truth(0.1, 0.0, turn(rng));
        const CPose2D odometry(odometryScale * truth.x(), 0.0, truth.phi());
        const double y = noise(rng), dx = noise(rng);  // one draw per statement
        const CPose2D registered(truth.x() + dx, y, truth.phi());
        calibration.observe(odometry, registered, covariance);
    }
}

}  // namespace

TEST(OdometryCalibration, LearnsHowLongTheOdometryReadsFromWellRegisteredScans) {
    // intel's odometry reads about 4.5 % long (B3). 2 mm of registration noise on 0.1 m steps
    // is 2 % per step; over 20 m (200 steps) the scale's sigma is 0.14 %: within 3 sigmas.
    OdometryCalibration calibration(on());
    std::mt19937 rng(1);
    drive(calibration, 20, 1.045, rng);
    EXPECT_NEAR(calibration.scale(), 1 / 1.045, 0.0045);
    EXPECT_NEAR(calibration.evidenceDistance(), 20 * 1.045, 0.2);
    // The corrected increment is the true motion; the turn is left alone.
    const CPose2D corrected = calibration.corrected(CPose2D(1.045, 0.0, 0.3));
    EXPECT_NEAR(corrected.x(), 1.0, 0.005);
    EXPECT_DOUBLE_EQ(corrected.phi(), 0.3);
}

TEST(OdometryCalibration, AppliesNothingBeforeEnoughEvidenceOrWhenOff) {
    std::mt19937 rng(2);
    OdometryCalibration early(on());  // min_distance 10 m of odometry
    drive(early, 9, 1.05, rng);
    EXPECT_DOUBLE_EQ(early.scale(), 1.0) << "9.5 m of evidence: not yet";
    // 90 steps: sigma 0.2 %, within 3 sigmas.
    EXPECT_NEAR(early.estimate(), 1 / 1.05, 0.006) << "though it is learnt already";
    drive(early, 1, 1.05, rng);
    EXPECT_NEAR(early.scale(), 1 / 1.05, 0.006);

    OdometryCalibration disabled({});  // off by default
    drive(disabled, 20, 1.05, rng);
    EXPECT_DOUBLE_EQ(disabled.scale(), 1.0);
    const CPose2D increment(0.3, 0.01, 0.05);
    EXPECT_EQ(disabled.corrected(increment), increment);
}

TEST(OdometryCalibration, ScansACorridorLeavesUndeterminedDoNotCount) {
    // In a corridor, registration keeps the prediction along it (registered = odometry):
    // counted, such scans would pull the scale towards 1 however long the odometry reads.
    OdometryCalibration calibration(on());
    std::mt19937 rng(3);
    drive(calibration, 10, 1.03, rng);
    for (int i = 0; i < 1000; ++i) {
        const CPose2D odometry(0.103, 0.0, 0.0);
        calibration.observe(odometry, odometry, corridorAlongX());
    }
    EXPECT_NEAR(calibration.scale(), 1 / 1.03, 0.006);  // 100 steps: sigma 0.2 %
    EXPECT_NEAR(calibration.evidenceDistance(), 10 * 1.03, 0.2);
}

TEST(OdometryCalibration, TurnsOnTheSpotSayNothingAndTheScaleIsBounded) {
    OdometryCalibration calibration(on());  // max_correction 0.1
    std::mt19937 rng(4);
    for (int i = 0; i < 100; ++i)  // turning on the spot: the registration jitters by mm
        calibration.observe(CPose2D(0, 0, 0.2), CPose2D(0.002, -0.001, 0.2), wellDetermined());
    EXPECT_DOUBLE_EQ(calibration.evidenceDistance(), 0.0);
    EXPECT_DOUBLE_EQ(calibration.estimate(), 1.0);
    drive(calibration, 20, 1.4, rng);  // a broken odometry, not a biased one
    EXPECT_DOUBLE_EQ(calibration.scale(), 0.9);
}
