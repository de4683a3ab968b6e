// The MRPT face of the matcher: CScanFeaturesMap (a CMetricMap holding one scan and its
// features) and CGraphMatcherAlignment (a CMetricMapsAlignmentAlgorithm), on scans simulated
// with a laser mounted off the robot's centre and inserted at non-trivial robot poses. The
// real feature extractor runs on the scans here.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/mrptslam/CGraphMatcherAlignment.h>

#include <cmath>
#include <random>

#include "SyntheticScans.h"

using mrpt::poses::CPose2D;
using namespace toposlam::matching;
using toposlam::mrptslam::CGraphMatcherAlignment;
using toposlam::mrptslam::TGraphMatcherAlignmentResult;

namespace {
toposlam::simulation::LaserModel offsetLaser() {
    auto laser = toposlam::test::fullCircleLaser(360, 20.0);
    laser.sensorPose = mrpt::poses::CPose3D(0.25, -0.05, 0.3, 0.1, 0, 0);  // x y z yaw
    return laser;
}

CScanFeaturesMap mapOf(const CPose2D& robotInWorld, const CPose2D& insertedAt) {
    std::mt19937 rng(5);
    const auto scan = toposlam::simulation::simulateScan(toposlam::test::asymmetricRoom(),
                                                         offsetLaser(), robotInWorld, rng);
    CScanFeaturesMap m("corners");
    m.insertObservation(scan, mrpt::poses::CPose3D(insertedAt));
    return m;
}

double angleError(double a, double b) {
    return std::abs(mrpt::math::wrapToPi(a - b));
}
}  // namespace

// Map m1 holds the scan at robot pose A inserted at IA, m2 the scan at B inserted at IB:
// the pose of m2 in m1 is IA + (B - A) - IB. Noise-free points: the refined pose is exact to
// the millimetre (the scan-mode ICP's accuracy on exact data), so 5 mm / 5 mrad.
TEST(CGraphMatcherAlignment, AlignPdfGivesThePoseOfM2InM1WithoutGuess) {
    const CPose2D A(3.0, 2.0, 0.3), B(3.7, 2.5, -0.9);
    const CPose2D IA(10, -4, 1.0), IB(0, 0, 0);
    const CScanFeaturesMap m1 = mapOf(A, IA), m2 = mapOf(B, IB);
    ASSERT_FALSE(m1.isEmpty());
    ASSERT_GE(m1.features().segments.size(), 4u);
    const CPose2D expected = IA + (B - A) - IB;

    CGraphMatcherAlignment align;
    align.options.useGuess = false;
    TGraphMatcherAlignmentResult info;
    const auto pdf = align.Align(&m1, &m2, CPose2D(), info);
    const auto* g = dynamic_cast<const mrpt::poses::CPosePDFGaussian*>(pdf.get());
    ASSERT_NE(g, nullptr) << "AlignPDF returns a CPosePDFGaussian";
    EXPECT_TRUE(info.match.reliable()) << toString(info.match.status);
    EXPECT_NEAR(g->mean.x(), expected.x(), 5e-3);
    EXPECT_NEAR(g->mean.y(), expected.y(), 5e-3);
    EXPECT_LT(angleError(g->mean.phi(), expected.phi()), 5e-3);
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(g->cov(k, k), 0.0);
        EXPECT_LT(g->cov(k, k), 1e-3);
    }
    EXPECT_GT(info.executionTime, 0.0);
}

// Tracking: an odometry guess 0.6 m and 20 deg off still lands on the truth.
TEST(CGraphMatcherAlignment, UsesTheGuessWhenAsked) {
    const CPose2D A(4.0, 2.0, 0.0), B(4.5, 2.4, 0.5);
    const CScanFeaturesMap m1 = mapOf(A, CPose2D()), m2 = mapOf(B, CPose2D());
    const CPose2D expected = B - A;
    CGraphMatcherAlignment align;
    mrpt::poses::CPosePDFGaussian guess(expected + CPose2D(0.4, -0.45, 20 * M_PI / 180));
    const auto pdf = align.AlignPDF(&m1, &m2, guess);
    const auto& g = dynamic_cast<const mrpt::poses::CPosePDFGaussian&>(*pdf);
    EXPECT_NEAR(g.mean.x(), expected.x(), 5e-3);
    EXPECT_NEAR(g.mean.y(), expected.y(), 5e-3);
    EXPECT_LT(angleError(g.mean.phi(), expected.phi()), 5e-3);
}

// A symmetric scene gives no reliable pose: the PDF says so with a huge covariance.
TEST(CGraphMatcherAlignment, UnreliableMatchHasHugeCovariance) {
    toposlam::simulation::PolygonWorld square;
    square.addPolygon({{-3, -3}, {3, -3}, {3, 3}, {-3, 3}});
    auto laser = toposlam::test::fullCircleLaser();
    std::mt19937 rng(1);
    CScanFeaturesMap m1("corners"), m2("corners");
    m1.insertObservation(toposlam::simulation::simulateScan(square, laser, CPose2D(0, 0, 0), rng));
    m2.insertObservation(
        toposlam::simulation::simulateScan(square, laser, CPose2D(0, 0, 0.4), rng));
    CGraphMatcherAlignment align;
    align.options.useGuess = false;
    TGraphMatcherAlignmentResult info;
    const auto pdf = align.Align(&m1, &m2, CPose2D(), info);
    const auto& g = dynamic_cast<const mrpt::poses::CPosePDFGaussian&>(*pdf);
    EXPECT_FALSE(info.match.reliable()) << toString(info.match.status);
    EXPECT_GE(g.cov(0, 0), align.options.unreliableVariance);
}

TEST(CScanFeaturesMap, SerializesAndIsRegistered) {
    const CScanFeaturesMap m = mapOf(CPose2D(3, 2, 0.2), CPose2D(1, 1, 0.5));
    mrpt::io::CMemoryStream buffer;
    mrpt::serialization::archiveFrom(buffer) << m;
    buffer.Seek(0);
    const mrpt::serialization::CSerializable::Ptr obj =
        mrpt::serialization::archiveFrom(buffer).ReadObject();
    const auto back = std::dynamic_pointer_cast<CScanFeaturesMap>(obj);
    ASSERT_TRUE(back) << "read back as the same class (registered with mrpt-rtti)";
    EXPECT_EQ(back->extractor(), "corners");
    EXPECT_EQ(back->polar().validCount(), m.polar().validCount());
    EXPECT_EQ(back->features().segments.size(), m.features().segments.size());
    EXPECT_NEAR((back->sensorPose() - m.sensorPose()).norm(), 0.0, 1e-9);
}

TEST(CScanFeaturesMap, BuiltFromIniMapDefinitions) {
    mrpt::config::CConfigFileMemory ini;
    ini.write("map", "scanFeaturesMap_count", 1);
    ini.write("map_scanFeaturesMap_00_creationOpts", "extractor", "segments");
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(ini, "map");
    mrpt::maps::CMultiMetricMap maps;
    maps.setListOfMaps(defs);
    const auto m = maps.mapByClass<CScanFeaturesMap>();
    ASSERT_TRUE(m) << "scanFeaturesMap_count=1 creates a CScanFeaturesMap";
    EXPECT_EQ(m->extractor(), "segments");
}
