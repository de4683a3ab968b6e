// FeatureAssembly's rules beyond the paper's steps 4 and 5: a part that is no line is cut at
// its least-squares two-line breakpoint (TwoLineSplit), and a corner whose angle is too vague
// to mean anything is not reported.
#include <gtest/gtest.h>
#include <toposlam/features/FeatureAssembly.h>
#include <toposlam/features/TwoLineSplit.h>

#include <cmath>
#include <random>

using namespace toposlam::features;

namespace {

/// A room corner seen from the origin: the walls x = 2 and x cos(t) + y sin(t) = d, the
/// nearer one hit by each beam; n beams over `aperture` (centred on x), range noise sigma.
ScanPoints roomCorner(double t, double d, std::size_t n, double aperture, double sigma,
                      unsigned seed = 1) {
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(aperture);
    scan.maxRange = 100;
    scan.resizeScanAndAssign(n, 1.0f, true);
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, sigma > 0 ? sigma : 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = scan.getScanAngle(i);
        const double c = std::cos(a - t);
        const double r = std::min(2 / std::cos(a), c > 1e-9 ? d / c : HUGE_VAL);
        scan.setScanRange(i, static_cast<float>(r + (sigma > 0 ? noise(rng) : 0.0)));
    }
    ScanPoints p;
    p.assign(scan);
    return p;
}

/// Canonical index of the first beam at or beyond bearing b.
std::size_t beamAt(const ScanPoints& p, double b) {
    std::size_t k = 0;
    while (k < p.size() && std::atan2(p.y(k), p.x(k)) < b)
        ++k;
    return k;
}

}  // namespace

TEST(TwoLineSplit, CutsAtTheCornerEvenWhenItIsShallow) {
    // 135 deg room corner (a 45 deg chamfer) at (2, 1): the second wall is x + y = 3.
    const ScanPoints p = roomCorner(M_PI / 4, 3 / std::sqrt(2.0), 361, M_PI / 2, 0.0);
    const std::size_t corner = beamAt(p, std::atan2(1.0, 2.0));
    TwoLineSplit split;
    split.prepare(p, 0, p.size() - 1);
    std::size_t at = 0;
    ASSERT_TRUE(split.find(0, p.size() - 1, 4, at));
    EXPECT_LE(std::abs(static_cast<double>(at) - static_cast<double>(corner)), 1.0);
    // A piece of the prepared part: the same corner.
    ASSERT_TRUE(split.find(corner - 20, corner + 30, 4, at));
    EXPECT_LE(std::abs(static_cast<double>(at) - static_cast<double>(corner)), 1.0);
    // Too short for two pieces of 4 readings, or outside the prepared part.
    EXPECT_FALSE(split.find(0, 7, 4, at));
    split.prepare(p, 100, 200);
    EXPECT_FALSE(split.find(50, 150, 4, at));
}

TEST(FeatureAssembly, CutsAPartThatHoldsTwoWalls) {
    // The 135 deg corner of the test above, with noise, as one part (a missed corner).
    const double sigma = 0.01;
    ScanPoints p = roomCorner(M_PI / 4, 3 / std::sqrt(2.0), 361, M_PI / 2, sigma);
    const std::size_t corner = beamAt(p, std::atan2(1.0, 2.0));
    std::vector<LinePart> parts(1);
    parts[0].begin = 0;
    parts[0].end = static_cast<std::uint32_t>(p.size() - 1);

    FeatureAssembly assembly;
    ScanFeatures f;
    auto copy = parts;
    assembly.assemble(p, copy, sigma, f);
    EXPECT_TRUE(f.segments.empty());  // no line: dropped

    assembly.options.splitNonLines = true;
    copy = parts;
    assembly.assemble(p, copy, sigma, f);
    ASSERT_EQ(f.segments.size(), 2u);
    ASSERT_EQ(f.corners.size(), 1u);
    EXPECT_NEAR(f.corners[0].position.x, 2.0, 0.02);
    EXPECT_NEAR(f.corners[0].position.y, 1.0, 0.02);
    EXPECT_NEAR(f.corners[0].angle, 0.75 * M_PI, 2 * M_PI / 180);
    EXPECT_LE(std::abs(static_cast<double>(f.corners[0].beam) - static_cast<double>(corner)), 2);
}

TEST(FeatureAssembly, NoCornerWhoseAngleIsTooVague) {
    // Right-angle room corner at (2, 1); the second wall (y = 1) is seen by only 6 beams
    // 0.25 deg apart, 2 cm of wall: at 1 cm noise its direction is unknown.
    const double step = 0.25 * M_PI / 180, cornerBearing = std::atan2(1.0, 2.0);
    const std::size_t n = 2 * static_cast<std::size_t>(std::floor(cornerBearing / step)) + 13;
    const double aperture = static_cast<double>(n - 1) * step;
    FeatureAssembly assembly;
    assembly.options.cornerAngleSigmas = 3;
    ScanFeatures f;
    for (const double sigma : {0.0, 0.01}) {
        ScanPoints p = roomCorner(M_PI / 2, 1.0, n, aperture, sigma, 7);
        const std::size_t corner = beamAt(p, cornerBearing);
        ASSERT_GE(p.size() - corner, 6u);
        std::vector<LinePart> parts(2);
        parts[0].begin = 0;
        parts[0].end = static_cast<std::uint32_t>(corner - 2);
        parts[0].cornerAfter = true;
        parts[0].joint = static_cast<std::uint32_t>(corner - 1);
        parts[1].begin = static_cast<std::uint32_t>(corner);
        parts[1].end = static_cast<std::uint32_t>(p.size() - 1);
        assembly.assemble(p, parts, sigma, f);
        ASSERT_EQ(f.segments.size(), 2u) << "sigma " << sigma;
        if (sigma == 0) {
            ASSERT_EQ(f.corners.size(), 1u);  // exact readings: the angle is exact
            EXPECT_NEAR(f.corners[0].angle, M_PI / 2, 1e-6);
        } else {
            EXPECT_TRUE(f.corners.empty());  // the walls stay, their meeting ends are Open
            EXPECT_EQ(f.segments[0].endType, EndpointType::Open);
            EXPECT_EQ(f.segments[1].startType, EndpointType::Open);
        }
    }
    // Long walls on both sides: the corner stays at the same noise.
    ScanPoints p = roomCorner(M_PI / 2, 1.0, 361, M_PI / 2, 0.01, 7);
    const std::size_t corner = beamAt(p, cornerBearing);
    std::vector<LinePart> parts(2);
    parts[0].end = static_cast<std::uint32_t>(corner - 2);
    parts[0].cornerAfter = true;
    parts[0].joint = static_cast<std::uint32_t>(corner - 1);
    parts[1].begin = static_cast<std::uint32_t>(corner);
    parts[1].end = static_cast<std::uint32_t>(p.size() - 1);
    assembly.assemble(p, parts, 0.01, f);
    ASSERT_EQ(f.corners.size(), 1u);
    EXPECT_NEAR(f.corners[0].angle, M_PI / 2, 2 * M_PI / 180);
}
