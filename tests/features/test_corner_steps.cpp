// The corner paper's steps one by one: eq. (2), the exact slope difference, the merge rule
// (eq. 3), the corner fix and the two line fits.
#include <gtest/gtest.h>
#include <toposlam/features/CornerFix.h>
#include <toposlam/features/LeastSquaresLineFit.h>
#include <toposlam/features/SegmentMerge.h>
#include <toposlam/features/SlopeDifference.h>
#include <toposlam/features/TwoPointLineFit.h>

#include <cmath>
#include <functional>

using namespace toposlam::features;

namespace {

/// A scan of n beams over `aperture` whose reading at bearing a is rangeAt(a).
ScanPoints pointsOnBeams(const std::function<double(double)>& rangeAt, std::size_t n,
                         double aperture) {
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(aperture);
    scan.maxRange = 100;
    scan.resizeScanAndAssign(n, 1.0f, true);
    for (std::size_t i = 0; i < n; ++i) {
        scan.setScanRange(i, static_cast<float>(rangeAt(scan.getScanAngle(i))));
    }
    ScanPoints p;
    p.assign(scan);
    return p;
}

/// The wall x cos(t) + y sin(t) = d seen from the origin: r(a) = d / cos(a - t).
std::function<double(double)> wall(double t, double d) {
    return [t, d](double a) { return d / std::cos(a - t); };
}

}  // namespace

TEST(SlopeDifference, PaperEquationTwo) {
    // r = 2, 2.1, 2.3 with a 0.01 rad step: (0.1 / (2 * 0.01)) - (0.2 / (2.1 * 0.01)).
    EXPECT_NEAR(slopeDifferencePaper(2.0, 2.1, 2.3, 0.01), 5.0 - 0.2 / 0.021, 1e-12);
}

TEST(SlopeDifference, ExactFormIsZeroOnAnyStraightLine) {
    // Including grazing walls, where eq. (2)'s small-angle form drifts.
    for (const double t : {0.0, 0.5, 0.9}) {  // 0.9: up to 86 deg incidence
        const ScanPoints p = pointsOnBeams(wall(t, 3.0), 301, 1.2);
        for (std::size_t s : {1u, 3u, 20u}) {
            const double a = static_cast<double>(s) * p.angularStep();
            for (std::size_t k = s; k + s < p.size(); k += 7) {
                const double dk = slopeDifferenceExact(p.range(k - s), p.range(k), p.range(k + s),
                                                       std::cos(a), std::sin(a));
                EXPECT_NEAR(dk, 0, 1e-4) << "t " << t << " s " << s << " k " << k;
            }
        }
    }
    // The paper's form agrees to first order on a wall seen head-on...
    const ScanPoints head = pointsOnBeams(wall(0, 3.0), 301, 0.2);
    EXPECT_NEAR(
        slopeDifferencePaper(head.range(149), head.range(150), head.range(151), head.angularStep()),
        0, 0.01);
}

TEST(SlopeDifference, CornerMakesAPeak) {
    // Two walls meeting at (3, 0): x + y = 3 and x - y = 3, i.e. a 90-degree corner.
    const ScanPoints p = pointsOnBeams(
        [](double a) {
            return a < 0 ? 3 / (std::cos(a) - std::sin(a)) : 3 / (std::cos(a) + std::sin(a));
        },
        201, 0.4);
    SlopeDifference sd;
    std::vector<PointRun> runs = {{0, 200, EndpointType::Open, EndpointType::Open}};
    sd.compute(p, runs, true, 0.6, 0, 3);
    // The corner is on beam 100 (bearing 0), the farthest point (concave): the chord slope
    // tan(phi) goes from +1 to -1, so dk = k(before) - k(after) = +2 there.
    EXPECT_NEAR(sd.value(100), 2, 0.05);
    EXPECT_NEAR(sd.value(60), 0, 0.01);
}

TEST(SegmentMerge, MergesSlightBendsNotCornersOrHairpins) {
    // Readings of a polyline: the ray at bearing a hits its nearest edge.
    const auto polyline = [](std::vector<mrpt::math::TPoint2D> v) {
        return [v](double a) {
            double best = HUGE_VAL;
            const double dx = std::cos(a), dy = std::sin(a);
            for (std::size_t i = 0; i + 1 < v.size(); ++i) {
                const double ex = v[i + 1].x - v[i].x, ey = v[i + 1].y - v[i].y;
                const double den = dx * ey - dy * ex;
                if (std::abs(den) < 1e-12)
                    continue;
                const double t = (v[i].x * ey - v[i].y * ex) / den;
                const double s = (v[i].x * dy - v[i].y * dx) / den;
                if (t > 0 && s >= 0 && s <= 1)
                    best = std::min(best, t);
            }
            return best;
        };
    };
    const auto joinedParts = [](const ScanPoints& p) {
        // Split at the middle reading, as step 1 would at a corner there.
        const std::uint32_t mid = static_cast<std::uint32_t>(p.size() / 2),
                            last = static_cast<std::uint32_t>(p.size() - 1);
        return std::vector<LinePart>{{0, mid, true, mid}, {mid, last, false, 0}};
    };
    for (const auto& [bendDeg, merges] : std::vector<std::pair<double, bool>>{
             {10.0, true}, {15.0, true}, {20.0, false}, {90.0, false}}) {
        // A wall along +y through (3, -1) .. (3, 0), then turning left by bendDeg.
        const double b = bendDeg * M_PI / 180;
        const ScanPoints p =
            pointsOnBeams(polyline({{3, -1}, {3, 0}, {3 - std::sin(b), std::cos(b)}}), 101,
                          2 * std::atan2(1.0, 3.0) - 0.01);
        auto parts = joinedParts(p);
        mergeSegments(p, 0.3, parts);
        EXPECT_EQ(parts.size(), merges ? 1u : 2u) << bendDeg << " deg";
    }
    // A narrow notch pointing away from the sensor (a hairpin: the two chords point back at
    // each other, 8 degrees apart as lines): never merged.
    const ScanPoints notch = pointsOnBeams(polyline({{2, -0.35}, {5, 0}, {2, 0.35}}), 101, 0.3);
    auto parts = joinedParts(notch);
    mergeSegments(notch, 0.3, parts);
    EXPECT_EQ(parts.size(), 2u);
}

TEST(CornerFix, MovesTheJointToTheSideOfTheTrueCorner) {
    SlopeDifference sd;
    sd.numerator = {0, 0.1, 1.9, 2.0, 0.2, 0.1, 0};
    sd.scale.assign(7, 1.0);
    sd.baseline = {0, 1, 1, 1, 1, 1, 0};
    // Corner found at 3; dk(2) is close to dk(3): the true corner lies between 2 and 3, so the
    // first line ends at 2.
    std::vector<LinePart> parts(2);
    parts[0] = {0, 3, true, 3};
    parts[1] = {3, 6, false, 0};
    fixCorners(sd, parts);
    EXPECT_EQ(parts[0].end, 2u);
    EXPECT_EQ(parts[1].begin, 3u);
    // Mirror image: the second line starts at 4.
    sd.numerator = {0, 0.1, 0.2, 2.0, 1.9, 0.1, 0};
    parts[0] = {0, 3, true, 3};
    parts[1] = {3, 6, false, 0};
    fixCorners(sd, parts);
    EXPECT_EQ(parts[0].end, 3u);
    EXPECT_EQ(parts[1].begin, 4u);
}

TEST(LineFits, TwoPointAndLeastSquaresAgreeOnExactLinesAndShareTheCentroid) {
    const ScanPoints p = pointsOnBeams(wall(0.4, 2.5), 101, 1.0);
    const LineFit two = fitTwoPoint(p, 10, 90), ls = fitLeastSquares(p, 10, 90);
    ASSERT_TRUE(two.ok && ls.ok);
    EXPECT_NEAR(two.line.theta, 0.4, 1e-6);
    EXPECT_NEAR(two.line.rho, 2.5, 1e-6);
    EXPECT_NEAR(ls.line.theta, 0.4, 1e-6);
    EXPECT_NEAR(ls.line.rho, 2.5, 1e-6);
    EXPECT_LT(two.residualRms, 1e-6);
    // 81 readings: the two-point fit uses 40 + 40 (the middle one is left out).
    double cx = 0, cy = 0;
    for (std::size_t k = 10; k <= 90; ++k) {
        if (k == 50)
            continue;
        cx += p.x(k) / 80;
        cy += p.y(k) / 80;
    }
    EXPECT_NEAR(two.anchor.x, cx, 1e-9);
    EXPECT_NEAR(two.anchor.y, cy, 1e-9);
    // Two-point direction variance is 4/3 of least squares' for evenly spread points
    // (approximately here: the spacing along a slanted wall is not quite even).
    EXPECT_NEAR(two.directionVarFactor / ls.directionVarFactor, 4.0 / 3.0, 0.1);
    // A vertical line (x = 2 in the sensor frame) is no special case.
    const ScanPoints v = pointsOnBeams(wall(0, 2.0), 51, 1.0);
    const LineFit vt = fitTwoPoint(v, 0, 50);
    EXPECT_NEAR(vt.line.theta, 0, 1e-6);
    EXPECT_NEAR(vt.line.rho, 2, 1e-6);
}
