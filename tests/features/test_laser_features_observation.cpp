// CObservationLaserFeatures (serialization, registration, description) and the corners as
// CObservationBearingRange.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/CornerBearingRange.h>
#include <toposlam/features/CornerExtractor.h>

#include <cmath>
#include <sstream>

#include "FeatureTestScenes.h"

using namespace toposlam;
using namespace toposlam::features;

namespace {
ScanFeatures someFeatures(mrpt::obs::CObservation2DRangeScan& scanOut) {
    const auto scene = test::roomWithBox();
    scanOut = test::scanOf(scene, mrpt::poses::CPose2D(0.2, -0.4, 0.3), 361, M_PI, 0.01);
    CornerExtractor ex;
    ScanFeatures f;
    ex.extract(scanOut, f);
    return f;
}
}  // namespace

TEST(CObservationLaserFeatures, RegisteredWithMrptWhenTheLibraryIsLoaded) {
    const auto* cls =
        mrpt::rtti::findRegisteredClass("toposlam::features::CObservationLaserFeatures");
    ASSERT_NE(cls, nullptr) << "MRPT_INITIALIZER did not register the class";
    EXPECT_TRUE(cls->derivedFrom("CObservation"));
}

TEST(CObservationLaserFeatures, SerializationRoundTripKeepsEverything) {
    mrpt::obs::CObservation2DRangeScan scan;
    CObservationLaserFeatures obs;
    obs.features = someFeatures(scan);
    ASSERT_FALSE(obs.features.corners.empty());
    obs.timestamp = mrpt::Clock::fromDouble(1234.5);
    obs.sensorLabel = "LASER_FEATURES";
    obs.sensorPose = mrpt::poses::CPose3D(0.2, 0.01, 0.3, 0.1, 0, 0);
    obs.extractor = "corners";
    obs.scanLabel = "LASER";

    mrpt::io::CMemoryStream buf;
    auto out = mrpt::serialization::archiveFrom(buf);
    out << obs;
    buf.Seek(0);
    auto in = mrpt::serialization::archiveFrom(buf);
    const auto object = in.ReadObject();
    const auto back = std::dynamic_pointer_cast<CObservationLaserFeatures>(object);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->timestamp, obs.timestamp);
    EXPECT_EQ(back->sensorLabel, obs.sensorLabel);
    EXPECT_EQ(back->extractor, obs.extractor);
    EXPECT_EQ(back->scanLabel, obs.scanLabel);
    EXPECT_NEAR((back->sensorPose - obs.sensorPose).norm(), 0, 1e-12);
    const ScanFeatures &a = obs.features, &b = back->features;
    ASSERT_EQ(a.segments.size(), b.segments.size());
    ASSERT_EQ(a.corners.size(), b.corners.size());
    ASSERT_EQ(a.endpoints.size(), b.endpoints.size());
    for (std::size_t i = 0; i < a.segments.size(); ++i) {
        EXPECT_EQ(a.segments[i].start.x, b.segments[i].start.x);
        EXPECT_EQ(a.segments[i].end.y, b.segments[i].end.y);
        EXPECT_EQ(a.segments[i].line.theta, b.segments[i].line.theta);
        EXPECT_EQ(a.segments[i].firstBeam, b.segments[i].firstBeam);
        EXPECT_EQ(a.segments[i].lastBeam, b.segments[i].lastBeam);
        EXPECT_EQ(a.segments[i].startType, b.segments[i].startType);
        EXPECT_EQ(a.segments[i].residualRms, b.segments[i].residualRms);
    }
    for (std::size_t i = 0; i < a.corners.size(); ++i) {
        EXPECT_EQ(a.corners[i].position.x, b.corners[i].position.x);
        EXPECT_EQ(a.corners[i].angle, b.corners[i].angle);
        EXPECT_EQ(a.corners[i].beam, b.corners[i].beam);
        EXPECT_EQ(a.corners[i].segmentAfter, b.corners[i].segmentAfter);
        EXPECT_EQ(a.corners[i].covariance(0, 1), b.corners[i].covariance(1, 0));
        EXPECT_EQ(a.corners[i].type, b.corners[i].type);
    }
    for (std::size_t i = 0; i < a.endpoints.size(); ++i) {
        EXPECT_EQ(a.endpoints[i].position.y, b.endpoints[i].position.y);
        EXPECT_EQ(a.endpoints[i].type, b.endpoints[i].type);
        EXPECT_EQ(a.endpoints[i].beam, b.endpoints[i].beam);
    }
}

TEST(CObservationLaserFeatures, DescriptionListsTheFeatures) {
    mrpt::obs::CObservation2DRangeScan scan;
    CObservationLaserFeatures obs;
    obs.features = someFeatures(scan);
    obs.extractor = "corners";
    std::ostringstream text;
    obs.getDescriptionAsText(text);
    const std::string s = text.str();
    EXPECT_NE(s.find("CObservationLaserFeatures"), std::string::npos);
    EXPECT_NE(s.find("Corners: " + std::to_string(obs.features.corners.size())), std::string::npos);
    EXPECT_NE(s.find("Segments: " + std::to_string(obs.features.segments.size())),
              std::string::npos);
}

TEST(CObservationLaserFeatures, RobotFrameFeaturesApplyTheSensorPose) {
    CObservationLaserFeatures obs;
    obs.features.corners.resize(1);
    obs.features.corners[0].position = {1, 0};
    obs.sensorPose = mrpt::poses::CPose3D(0.5, 0, 0.2, M_PI / 2, 0, 0);
    const ScanFeatures r = obs.robotFrameFeatures();
    EXPECT_NEAR(r.corners[0].position.x, 0.5, 1e-12);
    EXPECT_NEAR(r.corners[0].position.y, 1.0, 1e-12);
}

TEST(CornerBearingRange, RangeYawAndPropagatedCovariance) {
    mrpt::obs::CObservation2DRangeScan scan;
    const ScanFeatures f = someFeatures(scan);
    ASSERT_FALSE(f.corners.empty());
    mrpt::obs::CObservationBearingRange br;
    std::vector<std::int32_t> ids(f.corners.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
        ids[i] = static_cast<std::int32_t>(10 + i);
    cornersToBearingRange(f, scan, br, ids);
    ASSERT_EQ(br.sensedData.size(), f.corners.size());
    EXPECT_TRUE(br.validCovariances);
    EXPECT_EQ(br.maxSensorDistance, scan.maxRange);
    for (std::size_t i = 0; i < f.corners.size(); ++i) {
        const auto& m = br.sensedData[i];
        const auto& c = f.corners[i];
        // Back to Cartesian: the same point (float storage: 1e-6 relative).
        EXPECT_NEAR(m.range * std::cos(m.yaw), c.position.x, 1e-5);
        EXPECT_NEAR(m.range * std::sin(m.yaw), c.position.y, 1e-5);
        EXPECT_EQ(m.landmarkID, static_cast<std::int32_t>(10 + i));
        // Total variance is invariant under the (orthogonal up to the 1/r scaling of yaw)
        // change of coordinates: var_r + r^2 var_yaw = trace of the Cartesian covariance.
        const double trace = c.covariance(0, 0) + c.covariance(1, 1);
        EXPECT_NEAR(m.covariance(0, 0) + m.range * m.range * m.covariance(1, 1), trace,
                    1e-9 + 1e-6 * trace);
        EXPECT_GT(m.covariance(2, 2), 0) << "pitch variance keeps the matrix invertible";
    }
    EXPECT_GT(br.sensor_std_range, 0);
    // Without ids: unknown landmarks.
    cornersToBearingRange(f, scan, br);
    EXPECT_EQ(br.sensedData[0].landmarkID, -1);
    EXPECT_THROW(cornersToBearingRange(f, scan, br, {1}), std::invalid_argument);
}
