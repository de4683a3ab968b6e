// io::MirrorImage: scans, poses and trajectories in the mirror image of the scene (y -> -y),
// checked against MRPT's own projection of the readings.
#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <toposlam/io/MirrorImage.h>

#include <cmath>
#include <vector>

using toposlam::io::mirroredPose;
using toposlam::io::mirroredScan;

namespace {

// 181 readings over 180 deg, 1 .. 2.8 m, every 7th invalid, with intensities.
mrpt::obs::CObservation2DRangeScan makeScan(bool rightToLeft, const mrpt::poses::CPose3D& pose) {
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(M_PI);
    scan.rightToLeft = rightToLeft;
    scan.maxRange = 30.0f;
    scan.sensorPose = pose;
    scan.resizeScan(181);
    scan.setScanHasIntensity(true);
    for (std::size_t i = 0; i < 181; ++i) {
        scan.setScanRange(i, 1.0f + 0.01f * static_cast<float>(i));
        scan.setScanRangeValidity(i, i % 7 != 3);
        scan.setScanIntensity(i, static_cast<int32_t>(i));
    }
    return scan;
}

// The points of the valid readings in the robot frame, in reading order (MRPT's projection).
std::vector<mrpt::math::TPoint3D> robotFramePoints(const mrpt::obs::CObservation2DRangeScan& scan) {
    mrpt::maps::CSimplePointsMap map;
    map.insertionOptions.minDistBetweenLaserPoints = 0;
    map.insertObservation(scan);
    std::vector<mrpt::math::TPoint3D> points(map.size());
    for (std::size_t i = 0; i < map.size(); ++i)
        map.getPoint(i, points[i]);
    return points;
}

}  // namespace

TEST(MirrorImage, EveryReadingLandsOnTheMirrorImageOfItsPoint) {
    const mrpt::poses::CPose3D mounts[] = {
        {0.2, 0.05, 0.3, 0.1, 0.0, 0.0},     // ahead and left of the centre, turned left
        {-0.3, -0.1, 0.2, M_PI, 0.0, 0.0},   // a rear laser
        {0.1, 0.2, 0.4, -0.4, 0.05, 0.03}};  // slightly tilted
    for (const bool rightToLeft : {true, false}) {
        for (const auto& mount : mounts) {
            SCOPED_TRACE(testing::Message() << "rightToLeft " << rightToLeft << ", " << mount);
            const auto scan = makeScan(rightToLeft, mount);
            const auto mirrored = mirroredScan(scan);
            const auto a = robotFramePoints(scan), b = robotFramePoints(*mirrored);
            ASSERT_EQ(a.size(), 155u);
            ASSERT_EQ(b.size(), a.size());
            // The readings are reversed: the last mirrored point is the first original one.
            for (std::size_t k = 0; k < a.size(); ++k) {
                const auto& p = a[k];
                const auto& q = b[b.size() - 1 - k];
                EXPECT_NEAR(q.x, p.x, 1e-5) << k;
                EXPECT_NEAR(q.y, -p.y, 1e-5) << k;
                EXPECT_NEAR(q.z, p.z, 1e-5) << k;
            }
            EXPECT_EQ(mirrored->getScanIntensity(0), 180);
            EXPECT_EQ(mirrored->rightToLeft, rightToLeft);
            EXPECT_EQ(mirrored->aperture, scan.aperture);
        }
    }
}

TEST(MirrorImage, TheMirrorImageOfTheMirrorImageIsTheOriginal) {
    const auto scan = makeScan(true, {0.2, 0.05, 0.3, 0.1, 0.02, -0.03});
    const auto twice = mirroredScan(*mirroredScan(scan));
    ASSERT_EQ(twice->getScanSize(), scan.getScanSize());
    for (std::size_t i = 0; i < scan.getScanSize(); ++i) {
        EXPECT_EQ(twice->getScanRange(i), scan.getScanRange(i)) << i;
        EXPECT_EQ(twice->getScanRangeValidity(i), scan.getScanRangeValidity(i)) << i;
        EXPECT_EQ(twice->getScanIntensity(i), scan.getScanIntensity(i)) << i;
    }
    EXPECT_LT(mrpt::poses::CPose3D(twice->sensorPose - scan.sensorPose).norm(), 1e-12);
    EXPECT_NEAR(twice->sensorPose.yaw(), scan.sensorPose.yaw(), 1e-12);
    EXPECT_NEAR(twice->sensorPose.pitch(), scan.sensorPose.pitch(), 1e-12);
    EXPECT_NEAR(twice->sensorPose.roll(), scan.sensorPose.roll(), 1e-12);
}

TEST(MirrorImage, PosesAndMotionsCompoundInTheMirrorImage) {
    const mrpt::poses::CPose2D a(1.0, 2.0, 0.5), b(-0.3, 0.7, -1.2);
    const auto m = mirroredPose(a);
    EXPECT_EQ(m.x(), 1.0);
    EXPECT_EQ(m.y(), -2.0);
    EXPECT_EQ(m.phi(), -0.5);
    // The reflection keeps compounding: a motion b from pose a lands, mirrored, where the
    // mirrored motion from the mirrored pose does; relative motions mirror alike.
    const auto lhs = mirroredPose(a + b), rhs = mirroredPose(a) + mirroredPose(b);
    EXPECT_NEAR(lhs.x(), rhs.x(), 1e-12);
    EXPECT_NEAR(lhs.y(), rhs.y(), 1e-12);
    EXPECT_NEAR(lhs.phi(), rhs.phi(), 1e-12);
    const auto rel = mirroredPose(b - a), relMirrored = mirroredPose(b) - mirroredPose(a);
    EXPECT_NEAR(rel.x(), relMirrored.x(), 1e-12);
    EXPECT_NEAR(rel.y(), relMirrored.y(), 1e-12);
    EXPECT_NEAR(rel.phi(), relMirrored.phi(), 1e-12);

    const toposlam::io::Trajectory2D t = {{10.5, {1, 2, 0.5}}, {11.5, {2, -1, -3}}};
    const auto mt = toposlam::io::mirroredTrajectory(t);
    ASSERT_EQ(mt.size(), 2u);
    EXPECT_EQ(mt[1].stamp, 11.5);
    EXPECT_EQ(mt[1].pose.y, 1.0);
    EXPECT_EQ(mt[1].pose.phi, 3.0);
}
