// smoothScanPositions: registration and odometry together place the scans between keyframes
// better than registration alone; keyframes and headings never move.
#include <gtest/gtest.h>
#include <toposlam/mapping/TrajectorySmoother.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace toposlam::mapping {
namespace {

using mrpt::poses::CPose2D;

// A robot driving an arc, a scan every 6 cm, a keyframe every 5th scan.
std::vector<CPose2D> arc(std::size_t n) {
    std::vector<CPose2D> truth;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 0.01 * double(i);
        truth.emplace_back(6 * std::sin(a), 6 * (1 - std::cos(a)), a);
    }
    return truth;
}

std::vector<SmoothingInput> observe(const std::vector<CPose2D>& truth, double registrationSigma,
                                    double odometrySigma, std::mt19937& rng) {
    std::normal_distribution<double> registration(0, registrationSigma), odometry(0, odometrySigma);
    std::vector<SmoothingInput> in(truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
        in[i].fixed = i % 5 == 0;
        if (in[i].fixed) {
            in[i].pose = truth[i];
        } else {
            const double dy = registration(rng), dx = registration(rng);  // one per statement
            in[i].pose = CPose2D(truth[i].x() + dx, truth[i].y() + dy, truth[i].phi());
        }
        in[i].poseVariance = registrationSigma * registrationSigma;
        if (i > 0) {
            const CPose2D step = truth[i] - truth[i - 1];
            const double dy = odometry(rng), dx = odometry(rng);
            in[i].odometry = CPose2D(step.x() + dx, step.y() + dy, step.phi());
            in[i].odometryVariance = odometrySigma * odometrySigma;
        }
    }
    return in;
}

double meanStepError(const std::vector<CPose2D>& poses, const std::vector<CPose2D>& truth) {
    double sum = 0;
    for (std::size_t i = 1; i < poses.size(); ++i) {
        const CPose2D e = (poses[i] - poses[i - 1]) - (truth[i] - truth[i - 1]);
        sum += e.norm();
    }
    return sum / double(poses.size() - 1);
}

TEST(TrajectorySmoother, ExactInputsStayWhereTheyAre) {
    const std::vector<CPose2D> truth = arc(50);
    std::mt19937 rng(1);
    std::vector<SmoothingInput> in = observe(truth, 1e-9, 1e-9, rng);
    const std::vector<CPose2D> out = smoothScanPositions(in);
    ASSERT_EQ(out.size(), truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
        EXPECT_NEAR(out[i].x(), truth[i].x(), 1e-6) << i;
        EXPECT_NEAR(out[i].y(), truth[i].y(), 1e-6) << i;
        EXPECT_EQ(out[i].phi(), in[i].pose.phi()) << i;
    }
}

// Registration 2 cm, odometry 1 cm per step, independent: together the steps come out closer
// to the truth than registration alone, keyframes exactly where they were.
TEST(TrajectorySmoother, RegistrationAndOdometryTogetherBeatRegistrationAlone) {
    const std::vector<CPose2D> truth = arc(400);
    std::mt19937 rng(7);
    const std::vector<SmoothingInput> in = observe(truth, 0.02, 0.01, rng);
    std::vector<CPose2D> registered;
    for (const SmoothingInput& s : in)
        registered.push_back(s.pose);
    const std::vector<CPose2D> out = smoothScanPositions(in);
    const double before = meanStepError(registered, truth);
    const double after = meanStepError(out, truth);
    EXPECT_LT(after, 0.6 * before) << before << " -> " << after;
    for (std::size_t i = 0; i < in.size(); i += 5) {
        EXPECT_EQ(out[i].x(), in[i].pose.x());
        EXPECT_EQ(out[i].y(), in[i].pose.y());
    }
}

// With no odometry a scan has only its registration: it stays where it is.
TEST(TrajectorySmoother, AScanWithoutOdometryKeepsItsRegistration) {
    const std::vector<CPose2D> truth = arc(12);
    std::mt19937 rng(3);
    std::vector<SmoothingInput> in = observe(truth, 0.02, 0.01, rng);
    in[7].odometry.reset();  // a jump into scan 7 and out of it
    in[8].odometry.reset();
    const std::vector<CPose2D> out = smoothScanPositions(in);
    EXPECT_NEAR(out[7].x(), in[7].pose.x(), 1e-12);
    EXPECT_NEAR(out[7].y(), in[7].pose.y(), 1e-12);
}

TEST(TrajectorySmoother, AFreeScanWithoutVarianceIsAnError) {
    std::vector<SmoothingInput> in(2);
    in[0].fixed = true;
    EXPECT_THROW(smoothScanPositions(in), std::invalid_argument);
}

}  // namespace
}  // namespace toposlam::mapping
