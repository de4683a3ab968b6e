#include <gtest/gtest.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <cmath>

using mrpt::math::TPoint2D;
using namespace toposlam::simulation;

namespace {
PolygonWorld squareRoom(double half) {
    PolygonWorld w;
    w.addPolygon({{-half, -half}, {half, -half}, {half, half}, {-half, half}});
    return w;
}
}  // namespace

TEST(PolygonWorld, RayHitsNearestWall) {
    const PolygonWorld w = squareRoom(2.0);
    EXPECT_NEAR(w.castRay({0, 0}, 0.0, 10), 2.0, 1e-12);
    EXPECT_NEAR(w.castRay({1, 0}, M_PI, 10), 3.0, 1e-12);
    EXPECT_NEAR(w.castRay({0, 0}, M_PI / 4, 10), 2.0 * std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(std::isinf(w.castRay({0, 0}, 0.0, 1.5))) << "beyond max range: no return";
}

TEST(PolygonWorld, DiscOccludesWall) {
    PolygonWorld w = squareRoom(2.0);
    w.addDisc({{1.0, 0.0}, 0.25});
    EXPECT_NEAR(w.castRay({0, 0}, 0.0, 10), 0.75, 1e-12);
}

TEST(LaserModel, ScanGeometryAndInvalidBeams) {
    const PolygonWorld w = squareRoom(2.0);
    LaserModel laser;
    laser.beams = 181;
    laser.aperture = M_PI;
    laser.maxRange = 2.5;
    std::mt19937 rng(1);
    const auto scan = simulateScan(w, laser, mrpt::poses::CPose2D(0, 0, 0), rng);
    ASSERT_EQ(scan.getScanSize(), 181u);
    EXPECT_NEAR(scan.getScanRange(90), 2.0, 1e-6);  // straight ahead
    EXPECT_NEAR(scan.getScanRange(0), 2.0, 1e-6);   // -90 deg
    EXPECT_FALSE(scan.getScanRangeValidity(45)) << "the -45 deg corner is 2.83 m > 2.5 m away";
    EXPECT_TRUE(scan.getScanRangeValidity(30));
}
