// SegmentExtractor (graph-matching paper, sec. 2.1): convex / concave / jump endpoints,
// convex-convex and concave-concave segments, arc rejection.
#include <gtest/gtest.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/InscribedAngleArcTest.h>
#include <toposlam/features/SegmentExtractor.h>

#include <cmath>
#include <functional>
#include <limits>

#include "FeatureTestScenes.h"

using namespace toposlam;
using namespace toposlam::features;
using mrpt::math::TPoint2D;

namespace {

/// Endpoint positions are readings (median-filtered), not intersections: they are within a
/// couple of beam spacings of the true vertex. 1081 beams over 270 deg at <= 7 m: spacing
/// <= 3 cm, so 0.07 m.
constexpr double kEndpointTolerance = 0.07;

std::vector<TPoint2D> endpointsOfType(const ScanFeatures& f, EndpointType t) {
    std::vector<TPoint2D> out;
    for (const Endpoint& e : f.endpoints) {
        if (e.type == t)
            out.push_back(e.position);
    }
    return out;
}

}  // namespace

TEST(SegmentExtractor, EndpointsAndSegmentsOfABoxInARoom) {
    // Sensor at the origin facing +x; the box [2,3] x [0.5,1.3] shows its faces x = 2 and
    // y = 0.5 (convex corner (2, 0.5), occluding edges (2, 1.3) and (3, 0.5)); the room
    // corners (5,-2), (5,4), (-3,4) are in view and concave.
    const auto scene = test::roomWithBox();
    const auto scan = test::scanOf(scene, mrpt::poses::CPose2D(0, 0, 0), 1081, 1.5 * M_PI);
    SegmentExtractor ex;
    ScanFeatures f;
    ex.extract(scan, f);

    const auto convex = endpointsOfType(f, EndpointType::Convex);
    const auto concave = endpointsOfType(f, EndpointType::Concave);
    const auto jumps = endpointsOfType(f, EndpointType::Jump);
    ASSERT_EQ(convex.size(), 1u);
    EXPECT_LT(test::nearest({2, 0.5}, convex), kEndpointTolerance);
    ASSERT_EQ(concave.size(), 3u);
    for (const TPoint2D& c : {TPoint2D(5, -2), TPoint2D(5, 4), TPoint2D(-3, 4)}) {
        EXPECT_LT(test::nearest(c, concave), kEndpointTolerance) << c.x << ", " << c.y;
    }
    EXPECT_LT(test::nearest({2, 1.3}, jumps), kEndpointTolerance);
    EXPECT_LT(test::nearest({3, 0.5}, jumps), kEndpointTolerance);

    // Segments: the two box faces (convex-convex) and the walls x = 5 (partly hidden by the
    // box, still > 30 % on the line) and y = 4 (concave-concave). Noise-free readings lie on
    // the walls exactly (float ranges: 1e-6 m), so the fitted lines are exact to 1e-5.
    const auto findLine = [&](double theta, double rho) -> const LineSegment* {
        for (const LineSegment& s : f.segments) {
            if (std::abs(std::remainder(s.line.theta - theta, 2 * M_PI)) < 1e-5 &&
                std::abs(s.line.rho - rho) < 1e-5) {
                return &s;
            }
        }
        return nullptr;
    };
    const LineSegment* face = findLine(0, 2);             // x = 2
    const LineSegment* bottom = findLine(M_PI / 2, 0.5);  // y = 0.5
    const LineSegment* farWall = findLine(0, 5);          // x = 5
    const LineSegment* leftWall = findLine(M_PI / 2, 4);  // y = 4
    ASSERT_NE(face, nullptr);
    ASSERT_NE(bottom, nullptr);
    ASSERT_NE(farWall, nullptr);
    ASSERT_NE(leftWall, nullptr);
    EXPECT_EQ(face->startType, EndpointType::Convex);  // scan order: from (2,0.5) up to (2,1.3)
    EXPECT_EQ(face->endType, EndpointType::Jump);
    EXPECT_EQ(farWall->startType, EndpointType::Concave);
    EXPECT_EQ(farWall->endType, EndpointType::Concave);
    EXPECT_NEAR(farWall->start.y, -2, kEndpointTolerance);
    EXPECT_NEAR(farWall->end.y, 4, kEndpointTolerance);
    EXPECT_EQ(f.segments.size(), 4u);
    EXPECT_TRUE(f.corners.empty());
}

TEST(SegmentExtractor, NoSegmentOnARoundPillar) {
    featureeval::SyntheticScene scene = test::roomWithBox();
    scene.discs.push_back({{2, -1}, 0.3});
    const auto scan = test::scanOf(scene, mrpt::poses::CPose2D(0, 0, 0), 1081, 1.5 * M_PI, 0.005);
    SegmentExtractor ex;
    ScanFeatures f;
    ex.extract(scan, f);
    // The pillar spans bearings atan2(-1, 2) +- asin(0.3 / sqrt(5)).
    const double centre = std::atan2(-1, 2), half = std::asin(0.3 / std::sqrt(5.0));
    for (const LineSegment& s : f.segments) {
        const double a = std::atan2(s.start.y, s.start.x), b = std::atan2(s.end.y, s.end.x);
        const bool onPillar = std::abs(a - centre) < half && std::abs(b - centre) < half;
        EXPECT_FALSE(onPillar) << "segment on the pillar from beam " << s.firstBeam;
    }
}

TEST(InscribedAngleArcTest, TellsArcsFromLinesAndCorners) {
    // Points on a circle arc, on a line and on a right-angle corner, as a scan would see them.
    // Build a scan whose readings are the wanted points: choose ranges along each beam.
    const auto pointsOnBeams = [](const std::function<double(double)>& rangeAt, std::size_t n,
                                  float aperture = 0.6f) {
        mrpt::obs::CObservation2DRangeScan scan;
        scan.aperture = aperture;
        scan.maxRange = 100;
        scan.resizeScanAndAssign(n, 1.0f, true);
        for (std::size_t i = 0; i < n; ++i) {
            scan.setScanRange(i, static_cast<float>(rangeAt(scan.getScanAngle(i))));
        }
        ScanPoints sp;
        sp.assign(scan);
        return sp;
    };
    const std::size_t n = 60;
    // Circle of radius 0.5 centred 3 m ahead (seen within +-9.6 deg): the near side, r(a)
    // from the ray-circle hit; beams within +-8.6 deg see an arc of about 120 deg.
    const ScanPoints arc = pointsOnBeams(
        [](double a) {
            const double b = 3 * std::cos(a);
            return b - std::sqrt(b * b - (9 - 0.25));
        },
        n, 0.3f);
    const ScanPoints line = pointsOnBeams([](double a) { return 3 / std::cos(a); }, n);
    const ScanPoints corner = pointsOnBeams(
        [](double a) {  // walls x + y = 3 and x - y = 3 meet at (3, 0)
            return a < 0 ? 3 / (std::cos(a) - std::sin(a)) : 3 / (std::cos(a) + std::sin(a));
        },
        n);
    InscribedAngleArcTest test;
    EXPECT_TRUE(test.isArc(arc, 0, n - 1));
    EXPECT_FALSE(test.isArc(line, 0, n - 1));
    EXPECT_FALSE(test.isArc(corner, 0, n - 1));
}

TEST(SegmentExtractor, SameFeaturesWhicheverWayTheScanRuns) {
    std::mt19937 rng(3);
    const auto scene = featureeval::makeSyntheticRoom(rng);
    const auto scan = test::scanOf(scene, scene.poses[0], 1081, 1.5 * M_PI, 0.01);
    SegmentExtractor a, b;
    ScanFeatures fa, fb;
    a.extract(scan, fa);
    b.extract(test::reversed(scan), fb);
    ASSERT_EQ(fa.endpoints.size(), fb.endpoints.size());
    ASSERT_EQ(fa.segments.size(), fb.segments.size());
    for (std::size_t i = 0; i < fa.endpoints.size(); ++i) {
        const Endpoint &ea = fa.endpoints[i], &eb = fb.endpoints[fa.endpoints.size() - 1 - i];
        EXPECT_EQ(ea.position.x, eb.position.x);
        EXPECT_EQ(ea.type, eb.type);
    }
}

TEST(SegmentExtractor, DegenerateScans) {
    for (const char* name : {"segments", "segments-paper"}) {
        auto ex = makeFeatureExtractor(name);
        ScanFeatures f;
        mrpt::obs::CObservation2DRangeScan scan;
        ex->extract(scan, f);
        EXPECT_TRUE(f.segments.empty() && f.endpoints.empty());
        scan.aperture = static_cast<float>(M_PI);
        scan.maxRange = 10;
        for (std::size_t valid = 0; valid <= 3; ++valid) {
            scan.resizeScanAndAssign(181, std::numeric_limits<float>::quiet_NaN(), true);
            for (std::size_t i = 0; i < valid; ++i)
                scan.setScanRange(50 + 2 * i, 3.0f);
            ex->extract(scan, f);
            EXPECT_TRUE(f.segments.empty()) << name << ", " << valid << " valid beams";
            for (const Endpoint& e : f.endpoints)
                EXPECT_TRUE(std::isfinite(e.position.x));
        }
    }
}
