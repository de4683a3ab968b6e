// TopoSLAM's readers accept TopoSLAM's rawlogs: a log annotated by toposlam-annotate-features
// (scan features, bearing-range corners) and rawlogs with other TopoSLAM or MRPT objects in
// them are read by LaserLogReader (features come with their scan), toposlam-convert,
// toposlam-eval-slam and toposlam-slam.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/rooms/CTopologicalMap.h>

#include <filesystem>

#include "TestSupport.h"

namespace fs = std::filesystem;
using toposlam::features::CObservationLaserFeatures;
using toposlam::io::LaserLogReader;
using toposlam::io::LaserLogRecord;
using toposlam::test::runApp;

namespace {

constexpr std::size_t kScans = 60;

std::string officeLog() {
    return toposlam::test::shareDir() + "/office/office.rawlog";
}

// Labels and stamps `features` as toposlam-annotate-features does for `scan`'s features.
void stampAsFeaturesOf(CObservationLaserFeatures& features,
                       const mrpt::obs::CObservation2DRangeScan& scan) {
    features.timestamp = scan.timestamp;
    features.sensorLabel = scan.sensorLabel + "_FEATURES";
    features.scanLabel = scan.sensorLabel;
}

// The first kScans scans of the simulated office log, annotated with corners and their
// bearing-range observations.
std::string annotate(const toposlam::test::TempDir& dir) {
    const std::string out = dir.file("annotated.rawlog.gz");
    const auto r =
        runApp("toposlam-annotate-features", officeLog() + " -q --bearing-range --max-scans " +
                                                 std::to_string(kScans) + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return out;
}

}  // namespace

TEST(AnnotatedLogs, ReaderHandsOutEachScanWithItsStoredFeatures) {
    toposlam::classes::registerTopoSlamClasses();
    toposlam::test::TempDir dir;
    const std::string annotated = annotate(dir);
    LaserLogReader reader(annotated);
    LaserLogReader original(officeLog());
    LaserLogRecord record, expected;
    std::size_t n = 0, corners = 0;
    while (reader.next(record)) {
        ASSERT_TRUE(original.next(expected));
        EXPECT_EQ(record.fileStamp, expected.fileStamp);
        EXPECT_EQ(record.odometry, expected.odometry);
        const auto features = record.laserFeatures();
        ASSERT_TRUE(features) << "scan " << n << " has no stored features";
        EXPECT_EQ(features->scanLabel, record.scan->sensorLabel);
        EXPECT_EQ(features->timestamp, record.scan->timestamp);
        corners += features->features.corners.size();
        ++n;
    }
    EXPECT_EQ(n, kScans);
    EXPECT_GT(corners, kScans) << "an office has corners in view";
    // A log without stored features hands out none.
    EXPECT_FALSE(expected.storedFeatures);
}

TEST(AnnotatedLogs, AppsThatReadLogsAcceptThem) {
    toposlam::test::TempDir dir;
    const std::string annotated = annotate(dir);
    const auto convert =
        runApp("toposlam-convert", annotated + " -o " + dir.file("plain.rawlog") +
                                       " --odometry-trajectory " + dir.file("odometry.txt"));
    ASSERT_EQ(convert.exitCode, 0) << convert.output;
    EXPECT_NE(convert.output.find(std::to_string(kScans) + " scans"), std::string::npos)
        << convert.output;
    const auto eval =
        runApp("toposlam-eval-slam", "--odometry-of " + annotated + " --ground-truth " +
                                         toposlam::test::shareDir() + "/office/office_gt.txt");
    ASSERT_EQ(eval.exitCode, 0) << eval.output;
    const auto slam =
        runApp("toposlam-slam", std::string(TOPOSLAM_CONFIG_DIR) + "/toposlam-slam.ini " +
                                    annotated + " -o " + dir.file("slam"));
    ASSERT_EQ(slam.exitCode, 0) << slam.output;
    EXPECT_NE(slam.output.find("scans: " + std::to_string(kScans)), std::string::npos)
        << slam.output;
}

// Sensory-frame format with the features in the scan's frame, and other objects between the
// frames: a topological map and a bearing-range observation are skipped.
TEST(AnnotatedLogs, SensoryFramesWithFeaturesAndForeignObjects) {
    toposlam::classes::registerTopoSlamClasses();
    toposlam::test::TempDir dir;
    const auto records = LaserLogReader::readAll(officeLog());
    const std::string path = dir.file("sf.rawlog.gz");
    {
        mrpt::io::CFileGZOutputStream file(path);
        auto out = mrpt::serialization::archiveFrom(file);
        for (std::size_t i = 0; i < 5; ++i) {
            mrpt::obs::CActionRobotMovement2D move;
            move.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0), {});
            mrpt::obs::CActionCollection actions;
            actions.insert(move);
            auto features = std::make_shared<CObservationLaserFeatures>();
            stampAsFeaturesOf(*features, *records[i].scan);
            mrpt::obs::CSensoryFrame frame;
            frame.insert(records[i].scan);
            frame.insert(features);
            out << actions << frame << toposlam::rooms::CTopologicalMap()
                << mrpt::obs::CObservationBearingRange();
        }
    }
    LaserLogReader reader(path);
    LaserLogRecord record;
    std::size_t n = 0;
    while (reader.next(record)) {
        ASSERT_TRUE(record.laserFeatures()) << n;
        EXPECT_EQ(record.laserFeatures()->timestamp, record.scan->timestamp);
        EXPECT_NEAR(record.odometry.x(), 0.1 * static_cast<double>(n + 1), 1e-9);
        ++n;
    }
    EXPECT_EQ(n, 5u);
}

TEST(AnnotatedLogs, FeaturesStoredWithAnUpsideDownScanAreLeftOut) {
    // They were extracted in the mirrored frame the reader turns the scan out of.
    toposlam::classes::registerTopoSlamClasses();
    toposlam::test::TempDir dir;
    const auto records = LaserLogReader::readAll(officeLog());
    const std::string path = dir.file("upside-down.rawlog.gz");
    {
        mrpt::io::CFileGZOutputStream file(path);
        auto out = mrpt::serialization::archiveFrom(file);
        for (std::size_t i = 0; i < 2; ++i) {
            auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>(*records[i].scan);
            if (i == 1) {
                scan->rightToLeft = !scan->rightToLeft;
                scan->sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, 0, M_PI);
            }
            CObservationLaserFeatures features;
            stampAsFeaturesOf(features, *scan);
            out << *scan << features;
        }
    }
    LaserLogReader reader(path);
    LaserLogRecord record;
    ASSERT_TRUE(reader.next(record));
    EXPECT_TRUE(record.laserFeatures()) << "an upright scan keeps its features";
    ASSERT_TRUE(reader.next(record));
    EXPECT_FALSE(record.laserFeatures());
    EXPECT_EQ(reader.upsideDownScans(), 1u);
}
