// Small objects close to the laser, in front of what lies behind (ForegroundObjects.h).
#include <gtest/gtest.h>
#include <toposlam/mapping/ForegroundObjects.h>
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/mapping/ScanRegistration.h>

#include <cmath>
#include <vector>

namespace toposlam::mapping {
namespace {

struct Disc {
    double x, y, radius;  // sensor frame, m
};

// 361 readings over 180 deg (x ahead) of a wall across the view, the line x = wallX (m, sensor
// frame), with `discs` (people) in front of it; readings beyond 20 m are invalid.
matching::PolarScan scanOf(double wallX, const std::vector<Disc>& discs) {
    constexpr std::size_t kBeams = 361;
    const double first = -M_PI / 2, step = M_PI / double(kBeams - 1);
    std::vector<float> ranges(kBeams);
    std::vector<char> valid(kBeams, 1);
    for (std::size_t b = 0; b < kBeams; ++b) {
        const double c = std::cos(first + step * double(b)), s = std::sin(first + step * double(b));
        // The wall is hit where the beam goes ahead.
        double range = c > 1e-6 ? wallX / c : 1e9;
        for (const Disc& d : discs) {  // nearest intersection of the ray with the circle
            const double along = d.x * c + d.y * s;
            const double across2 = d.x * d.x + d.y * d.y - along * along;
            if (along > 0 && across2 <= d.radius * d.radius)
                range = std::min(range, along - std::sqrt(d.radius * d.radius - across2));
        }
        ranges[b] = float(std::min(range, 30.0));
        valid[b] = range < 20.0;
    }
    matching::PolarScan scan;
    scan.assign(first, step, ranges, valid, 20.0);
    return scan;
}

TEST(ForegroundObjects, APersonJustAheadIsLeftOutAndTheWallBehindKept) {
    const matching::PolarScan scan = scanOf(3.0, {{0.8, 0.0, 0.25}});
    ForegroundObjects foreground;
    matching::PolarScan out;
    const std::size_t removed = foreground.remove(scan, {}, out);
    ASSERT_GT(removed, 10u);
    ASSERT_EQ(out.size(), scan.size());
    EXPECT_EQ(out.validCount(), scan.validCount() - removed);
    for (std::size_t b = 0; b < scan.size(); ++b) {
        if (!scan.valid(b))
            continue;
        // The person's readings (within 1 m) are gone, every wall reading is kept as it was.
        EXPECT_EQ(out.valid(b), scan.range(b) > 1.0) << "beam " << b;
        if (out.valid(b)) {
            EXPECT_EQ(out.range(b), scan.range(b));
        }
    }
}

TEST(ForegroundObjects, APersonCloseByMakesTheKeyframesEdgesLessCertain) {
    // The variance added to a keyframe's registration edges (foreground_edge_sigma_factor k):
    // (k^2 - 1) times the edge floor's, so an edge at the floor has k times its sigmas; none
    // for a scan of the bare wall or of a person beyond foreground_max_range, and none with
    // k = 1 (the default).
    GraphSlamOptions options;
    EXPECT_EQ(options.foregroundEdgeSigmaFactor, 1);
    options.foregroundEdgeSigmaFactor = 5;
    const matching::GraphMatcherOptions matcher;
    const ScanRegistration registration(options, matcher);
    const matching::PolarScan person = scanOf(3.0, {{0.8, 0.0, 0.25}});
    const mrpt::math::CMatrixDouble33 added = registration.foregroundEdgeVariance(person);
    const double xy = options.edgeMinSigmaXY, phi = options.edgeMinSigmaPhi;
    EXPECT_NEAR(std::sqrt(xy * xy + added(0, 0)), 5 * xy, 1e-12);
    EXPECT_NEAR(std::sqrt(xy * xy + added(1, 1)), 5 * xy, 1e-12);
    EXPECT_NEAR(std::sqrt(phi * phi + added(2, 2)), 5 * phi, 1e-12);
    EXPECT_EQ(added(0, 1), 0);
    EXPECT_EQ(added(0, 2), 0);
    EXPECT_EQ(registration.foregroundEdgeVariance(scanOf(3.0, {})).norm(), 0);
    EXPECT_EQ(registration.foregroundEdgeVariance(scanOf(3.0, {{2.2, 0.0, 0.25}})).norm(), 0);
    options.foregroundEdgeSigmaFactor = 1;
    const ScanRegistration off(options, matcher);
    EXPECT_EQ(off.foregroundEdgeVariance(person).norm(), 0);
}

TEST(ForegroundObjects, FarWideOrBarelyProtrudingObjectsStay) {
    ForegroundObjects foreground;
    matching::PolarScan out;
    const ForegroundObjectOptions options;  // 1.5 m, 0.8 m wide, 0.2 m in front
    // Beyond foreground_max_range.
    EXPECT_EQ(foreground.remove(scanOf(4.0, {{2.0, 0.0, 0.25}}), options, out), 0u);
    // Wider than foreground_max_width (a 1.2 m cabinet seen face on, as a wide disc).
    EXPECT_EQ(foreground.remove(scanOf(3.0, {{1.4, 0.0, 0.6}}), options, out), 0u);
    // A thin column against the wall: the readings beside it are not 0.2 m farther.
    EXPECT_EQ(foreground.remove(scanOf(1.3, {{1.2, 0.0, 0.1}}), options, out), 0u);
    // A scan with nothing in front leaves `out` untouched.
    matching::PolarScan untouched;
    EXPECT_EQ(foreground.remove(scanOf(3.0, {}), options, untouched), 0u);
    EXPECT_EQ(untouched.size(), 0u);
}

TEST(ForegroundObjects, TwoPeopleAreTwoObjects) {
    // Side by side with a gap the wall shows through: each is narrow enough on its own.
    const matching::PolarScan scan = scanOf(3.0, {{1.0, -0.4, 0.25}, {1.0, 0.4, 0.25}});
    ForegroundObjects foreground;
    matching::PolarScan out;
    EXPECT_GT(foreground.remove(scan, {}, out), 20u);
    for (std::size_t b = 0; b < out.size(); ++b)
        EXPECT_TRUE(!out.valid(b) || out.range(b) > 2.0) << "beam " << b;
}

TEST(ForegroundObjects, AnySaysWhetherRemoveWouldLeaveSomethingOut) {
    // The scans of the tests above, with and without objects in front.
    const ForegroundObjectOptions options;
    ForegroundObjects foreground;
    for (const matching::PolarScan& scan :
         {scanOf(3.0, {{0.8, 0.0, 0.25}}), scanOf(4.0, {{2.0, 0.0, 0.25}}),
          scanOf(3.0, {{1.4, 0.0, 0.6}}), scanOf(1.3, {{1.2, 0.0, 0.1}}), scanOf(3.0, {}),
          scanOf(3.0, {{1.0, -0.4, 0.25}, {1.0, 0.4, 0.25}}),
          scanOf(3.0, {{4.0, 0.0, 0.25}, {1.0, 0.4, 0.25}})}) {
        matching::PolarScan out;
        EXPECT_EQ(ForegroundObjects::any(scan, options), foreground.remove(scan, options, out) > 0);
    }
    EXPECT_TRUE(ForegroundObjects::any(scanOf(3.0, {{0.8, 0.0, 0.25}}), options));
    EXPECT_FALSE(ForegroundObjects::any(scanOf(3.0, {}), options));
}

}  // namespace
}  // namespace toposlam::mapping
