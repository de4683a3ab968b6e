// CornerExtractor (corner paper, steps 1-5): exact corners on noise-free scans, invariance to
// the beam order, degenerate scans, and the noise model of its covariance.
#include <gtest/gtest.h>
#include <toposlam/featureeval/FeatureGroundTruth.h>
#include <toposlam/featureeval/FeatureMetrics.h>
#include <toposlam/features/CornerExtractor.h>
#include <toposlam/features/FeatureExtractor.h>

#include <cmath>
#include <limits>

#include "FeatureTestScenes.h"

using namespace toposlam;
using namespace toposlam::features;
using mrpt::obs::CObservation2DRangeScan;

namespace {

// Noise-free scans store ranges as float: each point is off by at most 2^-24 of its range
// (< 1e-6 m within 15 m). Lines through such points, and their intersections at corner
// angles >= 40 deg, are off by a few times that: 1e-4 m leaves a wide margin while any
// reading of the wrong wall in a line (>= 1 beam spacing, > 4 mm here) would fail it.
constexpr double kExactPosition = 1e-4;  // m
constexpr double kExactAngle = 1e-4;     // rad

CornerExtractor extractorFor(const std::string& name) {
    auto e = makeFeatureExtractor(name);
    return *dynamic_cast<CornerExtractor*>(e.get());
}

/// Every ground-truth corner found at its exact position and angle, and no other corner
/// except near "don't care" vertices.
void expectExactCorners(const featureeval::SyntheticScene& scene, const mrpt::poses::CPose2D& pose,
                        const CObservation2DRangeScan& scan, const std::string& method) {
    CornerExtractor ex = extractorFor(method);
    ScanFeatures f;
    ex.extract(scan, f);
    const auto gt = featureeval::computeGroundTruth(scene, pose, scan);
    for (const auto& g : gt.corners) {
        if (g.dontCare)
            continue;
        const Corner* best = nullptr;
        double bestDist = HUGE_VAL;
        for (const Corner& c : f.corners) {
            const double d = std::hypot(c.position.x - g.position.x, c.position.y - g.position.y);
            if (d < bestDist) {
                bestDist = d;
                best = &c;
            }
        }
        ASSERT_NE(best, nullptr) << method << ": no corner at all";
        EXPECT_LT(bestDist, kExactPosition)
            << method << ": corner (" << g.position.x << ", " << g.position.y << ") missed";
        if (bestDist < kExactPosition) {
            EXPECT_NEAR(best->angle, g.angle, kExactAngle) << method;
            EXPECT_EQ(best->type, g.type) << method;
        }
    }
    for (const Corner& c : f.corners) {
        double d = HUGE_VAL;
        for (const auto& g : gt.corners) {
            d = std::min(d, std::hypot(c.position.x - g.position.x, c.position.y - g.position.y));
        }
        EXPECT_LT(d, 0.1) << method << ": spurious corner at (" << c.position.x << ", "
                          << c.position.y << ")";
    }
}

}  // namespace

TEST(CornerExtractor, ExactCornersInARoomWithABox) {
    const auto scene = test::roomWithBox();
    // Sensor yaw 0: walls parallel to the sensor's y axis are vertical lines (infinite slope).
    for (const auto& pose : {mrpt::poses::CPose2D(0, 0, 0), mrpt::poses::CPose2D(0.5, -0.7, 0.6),
                             mrpt::poses::CPose2D(-1, 2, -2.5)}) {
        for (const auto& [beams, aperture] :
             std::vector<std::pair<std::size_t, double>>{{361, M_PI}, {1081, 1.5 * M_PI}}) {
            const auto scan = test::scanOf(scene, pose, beams, aperture);
            for (const char* method : {"corners", "corners-ls", "corners-paper"}) {
                SCOPED_TRACE(std::to_string(beams) + " beams, pose " + pose.asString());
                expectExactCorners(scene, pose, scan, method);
            }
        }
    }
}

TEST(CornerExtractor, ExactCornersInRandomFurnishedRooms) {
    std::mt19937 rng(2024);
    for (int room = 0; room < 6; ++room) {
        const auto scene = featureeval::makeSyntheticRoom(rng);
        for (const auto& pose : scene.poses) {
            const auto scan = test::scanOf(scene, pose, 1081, 1.5 * M_PI);
            SCOPED_TRACE("room " + std::to_string(room) + " pose " + pose.asString());
            expectExactCorners(scene, pose, scan, "corners");
        }
    }
}

TEST(CornerExtractor, SameCornersWhicheverWayTheScanRuns) {
    std::mt19937 rng(7);
    const auto scene = featureeval::makeSyntheticRoom(rng);
    for (const double sigma : {0.0, 0.01}) {
        for (const char* method : {"corners", "corners-ls", "corners-paper"}) {
            const auto scan = test::scanOf(scene, scene.poses[0], 1081, 1.5 * M_PI, sigma);
            const auto mirrored = test::reversed(scan);
            CornerExtractor a = extractorFor(method), b = extractorFor(method);
            ScanFeatures fa, fb;
            a.extract(scan, fa);
            b.extract(mirrored, fb);
            ASSERT_EQ(fa.corners.size(), fb.corners.size()) << method << " sigma " << sigma;
            ASSERT_EQ(fa.segments.size(), fb.segments.size());
            const std::uint32_t last = static_cast<std::uint32_t>(scan.getScanSize() - 1);
            // Corners come in beam order, so the mirrored list is the reverse one.
            for (std::size_t i = 0; i < fa.corners.size(); ++i) {
                const Corner &ca = fa.corners[i], &cb = fb.corners[fa.corners.size() - 1 - i];
                EXPECT_EQ(ca.position.x, cb.position.x);
                EXPECT_EQ(ca.position.y, cb.position.y);
                EXPECT_EQ(ca.angle, cb.angle);
                EXPECT_EQ(ca.beam, last - cb.beam);
            }
            for (std::size_t i = 0; i < fa.segments.size(); ++i) {
                const LineSegment &sa = fa.segments[i],
                                  &sb = fb.segments[fa.segments.size() - 1 - i];
                EXPECT_EQ(sa.firstBeam, last - sb.lastBeam);
                EXPECT_EQ(sa.start.x, sb.end.x);
                EXPECT_EQ(sa.startType, sb.endType);
                EXPECT_LE(sb.firstBeam, sb.lastBeam);
            }
        }
    }
}

TEST(CornerExtractor, SegmentsAndCornersAreConsistent) {
    std::mt19937 rng(11);
    const auto scene = featureeval::makeSyntheticRoom(rng);
    const auto scan = test::scanOf(scene, scene.poses[1], 1081, 1.5 * M_PI, 0.01);
    CornerExtractor ex;
    ScanFeatures f;
    ex.extract(scan, f);
    ASSERT_FALSE(f.corners.empty());
    for (std::size_t i = 1; i < f.segments.size(); ++i) {
        EXPECT_LT(f.segments[i - 1].firstBeam, f.segments[i].firstBeam);
    }
    for (std::size_t i = 1; i < f.corners.size(); ++i) {
        EXPECT_LT(f.corners[i - 1].beam, f.corners[i].beam);
    }
    for (const Corner& c : f.corners) {
        const LineSegment &a = f.segments[c.segmentBefore], &b = f.segments[c.segmentAfter];
        EXPECT_LT(a.lastBeam, b.firstBeam);
        EXPECT_EQ(a.endType, c.type);
        EXPECT_EQ(b.startType, c.type);
        // The corner lies on both lines.
        EXPECT_NEAR(a.line.distance(c.position), 0, 1e-9);
        EXPECT_NEAR(b.line.distance(c.position), 0, 1e-9);
        EXPECT_GT(c.covariance(0, 0), 0);
        EXPECT_GT(c.covariance(0, 0) * c.covariance(1, 1) - c.covariance(0, 1) * c.covariance(1, 0),
                  0);
    }
    for (const LineSegment& s : f.segments) {
        EXPECT_NEAR(s.line.distance(s.start), 0, 1e-9);
        EXPECT_NEAR(s.line.distance(s.end), 0, 1e-9);
        EXPECT_LE(s.residualRms, 0.05);
    }
}

TEST(CornerExtractor, DegenerateScans) {
    CornerExtractor ex;
    ScanFeatures f;
    CObservation2DRangeScan scan;
    ex.extract(scan, f);  // empty
    EXPECT_TRUE(f.segments.empty() && f.corners.empty() && f.endpoints.empty());

    scan.aperture = static_cast<float>(M_PI);
    scan.maxRange = 10;
    scan.resizeScanAndAssign(181, 10.0f, false);  // all invalid
    ex.extract(scan, f);
    EXPECT_TRUE(f.segments.empty() && f.corners.empty());

    for (std::size_t valid = 1; valid <= 3; ++valid) {
        scan.resizeScanAndAssign(181, 10.0f, false);
        for (std::size_t i = 0; i < valid; ++i) {
            scan.setScanRange(90 + i, 2.0f);
            scan.setScanRangeValidity(90 + i, true);
        }
        ex.extract(scan, f);
        EXPECT_TRUE(f.corners.empty()) << valid << " valid beams";
        EXPECT_TRUE(f.segments.empty()) << valid << " valid beams: too short for a line";
    }

    // One beam, two beams: no angular step at all.
    for (std::size_t n = 1; n <= 2; ++n) {
        scan.resizeScanAndAssign(n, 2.0f, true);
        ex.extract(scan, f);
        EXPECT_TRUE(f.corners.empty());
    }
}

TEST(CornerExtractor, SingleWallIsOneSegmentWithoutCorners) {
    featureeval::SyntheticScene scene;
    scene.polygons.push_back({{2, -50}, {3, -50}, {3, 50}, {2, 50}});  // a wall at x = 2
    for (const double sigma : {0.0, 0.01}) {
        const auto scan = test::scanOf(scene, mrpt::poses::CPose2D(0, 0, 0), 361, M_PI, sigma);
        for (const char* method : {"corners", "corners-paper"}) {
            if (sigma > 0 && std::string(method) == "corners-paper")
                continue;  // the paper has no noise model
            auto ex = makeFeatureExtractor(method);
            ScanFeatures f;
            ex->extract(scan, f);
            EXPECT_TRUE(f.corners.empty()) << method << " sigma " << sigma;
            ASSERT_GE(f.segments.size(), 1u) << method;
            // The wall is vertical in the sensor frame: theta = 0, rho = 2.
            const LineSegment& longest = *std::max_element(
                f.segments.begin(), f.segments.end(),
                [](const LineSegment& a, const LineSegment& b) { return a.length() < b.length(); });
            EXPECT_NEAR(longest.line.rho, 2.0, 3 * sigma + 1e-6);
            EXPECT_NEAR(std::abs(std::remainder(longest.line.theta, M_PI)), 0, 0.01 + 1e-6);
        }
    }
}

TEST(CornerExtractor, NanInfiniteZeroAndMaxRangeReadingsAreBreaks) {
    const auto scene = test::roomWithBox();
    const mrpt::poses::CPose2D pose(0.3, 0.2, 0.4);
    const auto clean = test::scanOf(scene, pose, 1081, 1.5 * M_PI);
    CObservation2DRangeScan bad = clean, marked = clean;
    const std::vector<std::pair<std::size_t, float>> spoilt = {
        {100, std::numeric_limits<float>::quiet_NaN()},
        {101, std::numeric_limits<float>::infinity()},
        {400, 0.0f},
        {401, -1.0f},
        {700, clean.maxRange},
        {701, clean.maxRange + 5}};
    for (const auto& [i, r] : spoilt) {
        bad.setScanRange(i, r);  // validity flag still says "valid"
        marked.setScanRangeValidity(i, false);
    }
    CornerExtractor ex;
    ScanFeatures fb, fm;
    ex.extract(bad, fb);
    ex.extract(marked, fm);
    ASSERT_EQ(fb.corners.size(), fm.corners.size());
    for (std::size_t i = 0; i < fb.corners.size(); ++i) {
        EXPECT_EQ(fb.corners[i].position.x, fm.corners[i].position.x);
        EXPECT_TRUE(std::isfinite(fb.corners[i].position.x));
    }
    ASSERT_EQ(fb.segments.size(), fm.segments.size());
    for (std::size_t i = 0; i < fb.segments.size(); ++i) {
        EXPECT_TRUE(std::isfinite(fb.segments[i].line.rho));
        EXPECT_TRUE(std::isfinite(fb.segments[i].residualRms));
        EXPECT_EQ(fb.segments[i].firstBeam, fm.segments[i].firstBeam);
        EXPECT_EQ(fb.segments[i].lastBeam, fm.segments[i].lastBeam);
    }
}

TEST(CornerExtractor, AnyFieldOfViewIncludingAFullCircle) {
    const auto scene = test::roomWithBox();
    const mrpt::poses::CPose2D pose(0, 0.5, 0.3);
    for (const double aperture : {0.5 * M_PI, 2 * M_PI * (1 - 1.0 / 720)}) {
        const auto scan = test::scanOf(scene, pose, 720, aperture);
        expectExactCorners(scene, pose, scan, "corners");
    }
    // A full circle: all four room corners are seen (the box hides none from here).
    const auto scan = test::scanOf(scene, pose, 720, 2 * M_PI * (1 - 1.0 / 720));
    CornerExtractor ex;
    ScanFeatures f;
    ex.extract(scan, f);
    EXPECT_TRUE(ex.points().cyclic());
    std::vector<mrpt::math::TPoint2D> found;
    for (const Corner& c : f.corners)
        found.push_back(c.position);
    const auto local = [&](double x, double y) { return (mrpt::poses::CPose2D(x, y, 0) - pose); };
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{-3, -2}, {5, -2}, {5, 4}, {-3, 4}}) {
        const auto p = local(x, y);
        EXPECT_LT(test::nearest({p.x(), p.y()}, found), kExactPosition) << x << ", " << y;
    }
}

TEST(CornerExtractor, CovarianceMatchesTheScatterOfNoisyCorners) {
    // Many noisy scans of one corner: the spread of the extracted position should match the
    // covariance the extractor predicts from its line fits (within sampling error: with 200
    // samples the variance estimate is within +-30 % at 3 sigma; allow a factor 1.6).
    featureeval::SyntheticScene scene;
    scene.polygons.push_back({{-4, -3}, {4, -3}, {4, 3}, {-4, 3}});
    const mrpt::poses::CPose2D pose(0, 0, 0.3);
    const mrpt::math::TPoint2D truth = [&] {
        const auto p = mrpt::poses::CPose2D(4, 3, 0) - pose;
        return mrpt::math::TPoint2D(p.x(), p.y());
    }();
    CornerExtractor ex;
    ScanFeatures f;
    double sxx = 0, syy = 0, predictedXX = 0, predictedYY = 0;
    int n = 0;
    for (unsigned seed = 1; seed <= 200; ++seed) {
        const auto scan = test::scanOf(scene, pose, 1081, 1.5 * M_PI, 0.01, seed);
        ex.extract(scan, f);
        for (const Corner& c : f.corners) {
            if (std::hypot(c.position.x - truth.x, c.position.y - truth.y) > 0.1)
                continue;
            sxx += (c.position.x - truth.x) * (c.position.x - truth.x);
            syy += (c.position.y - truth.y) * (c.position.y - truth.y);
            predictedXX += c.covariance(0, 0);
            predictedYY += c.covariance(1, 1);
            ++n;
        }
    }
    ASSERT_GT(n, 190);
    EXPECT_GT(sxx / predictedXX, 1 / 1.6);
    EXPECT_LT(sxx / predictedXX, 1.6);
    EXPECT_GT(syy / predictedYY, 1 / 1.6);
    EXPECT_LT(syy / predictedYY, 1.6);
}

TEST(CornerExtractor, MeetsTheAccuracyTargetsOnNoisyScans) {
    // A quick version of benchmark B1 (sigma = 0.01 m, 1081 beams) on a few rooms: the
    // extractor must keep its recall, precision and position error near the targets
    // (>= 95 %, <= 0.02 m). Fewer scans than B1, so a margin for sampling: 0.9 / 0.03 m.
    std::mt19937 rng(99), noise(5);
    featureeval::FeatureScores scores;
    CornerExtractor ex;
    ScanFeatures f;
    for (int room = 0; room < 8; ++room) {
        const auto scene = featureeval::makeSyntheticRoom(rng);
        const auto world = scene.world();
        simulation::LaserModel laser;
        laser.beams = 1081;
        laser.aperture = 1.5 * M_PI;
        laser.rangeNoiseStd = 0.01;
        for (const auto& pose : scene.poses) {
            const auto scan = simulation::simulateScan(world, laser, pose, noise);
            ex.extract(scan, f);
            scores.add(f, featureeval::computeGroundTruth(scene, pose, scan));
        }
    }
    EXPECT_GT(scores.groundTruthCorners, 50u);
    EXPECT_GE(scores.recall(), 0.9);
    EXPECT_GE(scores.precision(), 0.9);
    EXPECT_LE(scores.positionRmseNear(), 0.03);
}
