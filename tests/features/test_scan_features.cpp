// The feature type: line geometry, frames, ordering helpers.
#include <gtest/gtest.h>
#include <toposlam/features/ScanFeatures.h>

#include <cmath>

using namespace toposlam::features;
using mrpt::math::TPoint2D;

TEST(Line2D, ThroughTwoPointsAnyDirection) {
    // Vertical, horizontal, through the origin and slanted lines: rho >= 0, both points on it.
    const std::vector<std::pair<TPoint2D, TPoint2D>> cases = {
        {{2, -1}, {2, 3}}, {{-1, -2}, {4, -2}}, {{-1, -1}, {1, 1}}, {{0.3, 5}, {-2, 0.1}}};
    for (const auto& [a, b] : cases) {
        const Line2D l = Line2D::through(a, b);
        EXPECT_GE(l.rho, 0);
        EXPECT_GT(l.theta, -M_PI);
        EXPECT_LE(l.theta, M_PI);
        EXPECT_NEAR(l.distance(a), 0, 1e-12);
        EXPECT_NEAR(l.distance(b), 0, 1e-12);
    }
    const Line2D vertical = Line2D::through({2, -1}, {2, 3});
    EXPECT_NEAR(vertical.theta, 0, 1e-12);
    EXPECT_NEAR(vertical.rho, 2, 1e-12);
}

TEST(Line2D, ProjectAndSignedDistance) {
    const Line2D l = Line2D::through({0, 1}, {1, 1});  // y = 1
    EXPECT_NEAR(std::abs(l.distance({5, 3})), 2, 1e-12);
    const TPoint2D p = l.project({5, 3});
    EXPECT_NEAR(p.x, 5, 1e-12);
    EXPECT_NEAR(p.y, 1, 1e-12);
}

TEST(ScanFeatures, TransformedMovesEverythingConsistently) {
    ScanFeatures f;
    LineSegment s;
    s.start = {1, 1};
    s.end = {3, 1};
    s.line = Line2D::through(s.start, s.end);
    f.segments.push_back(s);
    Corner c;
    c.position = {3, 1};
    c.covariance(0, 0) = 4e-4;  // 2 cm along x, 1 cm along y
    c.covariance(1, 1) = 1e-4;
    f.corners.push_back(c);
    f.endpoints.push_back({{3, 1}, EndpointType::Concave, 7});

    const mrpt::poses::CPose2D pose(10, -2, M_PI / 2);
    const ScanFeatures w = f.transformed(pose);
    // pose (+) (3,1) = (10 - 1, -2 + 3)
    EXPECT_NEAR(w.corners[0].position.x, 9, 1e-12);
    EXPECT_NEAR(w.corners[0].position.y, 1, 1e-12);
    EXPECT_NEAR(w.endpoints[0].position.x, 9, 1e-12);
    // The line still passes through the moved segment ends.
    EXPECT_NEAR(w.segments[0].line.distance(w.segments[0].start), 0, 1e-12);
    EXPECT_NEAR(w.segments[0].line.distance(w.segments[0].end), 0, 1e-12);
    EXPECT_GE(w.segments[0].line.rho, 0);
    // A quarter turn swaps the covariance axes.
    EXPECT_NEAR(w.corners[0].covariance(0, 0), 1e-4, 1e-15);
    EXPECT_NEAR(w.corners[0].covariance(1, 1), 4e-4, 1e-15);
    EXPECT_NEAR(w.corners[0].covariance(0, 1), 0, 1e-15);
}

TEST(ScanFeatures, ClearKeepsCapacity) {
    ScanFeatures f;
    f.segments.resize(10);
    f.corners.resize(5);
    const auto cap = f.segments.capacity();
    f.clear();
    EXPECT_TRUE(f.segments.empty());
    EXPECT_TRUE(f.corners.empty());
    EXPECT_EQ(f.segments.capacity(), cap);
    EXPECT_STREQ(toString(EndpointType::Jump), "jump");
}
