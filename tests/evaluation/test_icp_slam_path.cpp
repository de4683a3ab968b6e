#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/evaluation/IcpSlamPath.h>
#include <toposlam/io/InputError.h>

#include <TestSupport.h>

#include <fstream>
#include <string>
#include <vector>

using namespace toposlam::evaluation;
using namespace mrpt::obs;
using toposlam::io::InputError;
using toposlam::test::TempDir;

namespace {

// Stamps that survive mrpt::Clock's 100 ns ticks: what a rawlog can store.
const std::vector<double> kScanStamps = {1000.25, 1000.5, 1000.75};

CObservation2DRangeScan::Ptr scanAt(double stamp) {
    auto scan = CObservation2DRangeScan::Create();
    scan->resizeScan(3);
    for (std::size_t i = 0; i < 3; ++i)
        scan->setScanRange(i, 1.0f);
    scan->timestamp = mrpt::Clock::fromDouble(stamp);
    scan->sensorLabel = "LASER";
    return scan;
}

// Observation-only rawlog: odometry then scan at each stamp -> icp-slam steps 0..5, scans at
// steps 1, 3, 5.
std::string writeObservationRawlog(const TempDir& dir) {
    const std::string path = dir.file("obs.rawlog");
    mrpt::io::CFileGZOutputStream file(path);
    auto out = mrpt::serialization::archiveFrom(file);
    for (const double t : kScanStamps) {
        auto odo = CObservationOdometry::Create();
        odo->timestamp = mrpt::Clock::fromDouble(t);
        odo->sensorLabel = "ODOMETRY";
        out << odo;
        out << scanAt(t);
    }
    return path;
}

// Actions/sensory-frames rawlog: (action, frame) pairs -> steps 0..2, all with a scan.
std::string writeSensoryFrameRawlog(const TempDir& dir) {
    const std::string path = dir.file("sf.rawlog");
    mrpt::io::CFileGZOutputStream file(path);
    auto out = mrpt::serialization::archiveFrom(file);
    for (const double t : kScanStamps) {
        CActionCollection actions;
        CActionRobotMovement2D move;
        move.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0),
                                 CActionRobotMovement2D::TMotionModelOptions());
        actions.insert(move);
        out << actions;
        CSensoryFrame frame;
        frame.insert(scanAt(t));
        out << frame;
    }
    return path;
}

// log_estimated_path.txt as icp-slam prints it: "%i %f %f %f", pose k = (k, 2k, 0.1k).
std::string writePath(const TempDir& dir, std::size_t lines, const std::string& extra = "") {
    const std::string path = dir.file("log_estimated_path.txt");
    std::ofstream f(path);
    for (std::size_t k = 0; k < lines; ++k) {
        f << k << " " << double(k) << ".000000 " << 2.0 * k << ".000000 " << 0.1 * k << "\n";
    }
    f << extra;
    return path;
}

}  // namespace

TEST(IcpSlamPath, ObservationRawlogEveryObjectIsAStepScansCarryTheStamps) {
    TempDir dir;
    const std::string rawlog = writeObservationRawlog(dir);
    const IcpSlamSteps steps = icpSlamStepsOf(rawlog);
    EXPECT_EQ(steps.totalSteps, 6u);
    ASSERT_EQ(steps.scans.size(), 3u);

    const auto t = loadIcpSlamPath(writePath(dir, 6), rawlog);
    ASSERT_EQ(t.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t step = 2 * k + 1;  // the scan's line, not the odometry's
        EXPECT_EQ(steps.scans[k].step, step);
        EXPECT_NEAR(t[k].stamp, kScanStamps[k], 1e-6);  // Clock ticks are 100 ns
        EXPECT_DOUBLE_EQ(t[k].pose.x, double(step));
        EXPECT_DOUBLE_EQ(t[k].pose.y, 2.0 * step);
        EXPECT_NEAR(t[k].pose.phi, 0.1 * step, 1e-6);
    }
}

TEST(IcpSlamPath, SensoryFrameRawlogOneStepPerActionFramePair) {
    TempDir dir;
    const std::string rawlog = writeSensoryFrameRawlog(dir);
    const IcpSlamSteps steps = icpSlamStepsOf(rawlog);
    EXPECT_EQ(steps.totalSteps, 3u);
    ASSERT_EQ(steps.scans.size(), 3u);
    const auto t = loadIcpSlamPath(writePath(dir, 3), rawlog);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_NEAR(t[2].stamp, kScanStamps[2], 1e-6);
    EXPECT_DOUBLE_EQ(t[2].pose.x, 2.0);
}

TEST(IcpSlamPath, ScanStampsReplaceTheRawlogStamps) {
    TempDir dir;
    const std::string rawlog = writeObservationRawlog(dir);
    const std::vector<double> printed = {976052857.34, 976052857.1, 976052857.52};
    const auto t = loadIcpSlamPath(writePath(dir, 6), rawlog, &printed);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].stamp, printed[1]);
    const std::vector<double> tooFew = {1.0};
    EXPECT_THROW(loadIcpSlamPath(writePath(dir, 6), rawlog, &tooFew), InputError);
}

TEST(IcpSlamPath, PathOfAnotherRunIsAnInputError) {
    TempDir dir;
    const std::string rawlog = writeObservationRawlog(dir);
    EXPECT_THROW(loadIcpSlamPath(writePath(dir, 5), rawlog), InputError) << "one line short";
    EXPECT_THROW(loadIcpSlamPath(writePath(dir, 7), rawlog), InputError) << "one line more";
}

TEST(IcpSlamPath, MalformedPathFilesAreInputErrors) {
    TempDir dir;
    const std::string rawlog = writeObservationRawlog(dir);
    auto errorOf = [&](const std::string& extra) {
        try {
            loadIcpSlamPath(writePath(dir, 5, extra), rawlog);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(errorOf("5 1.0 2.0 0.5\n"), "");
    EXPECT_NE(errorOf("5 -nan 2.0 0.5\n").find("line 6"), std::string::npos) << "NaN pose";
    EXPECT_NE(errorOf("7 1.0 2.0 0.5\n").find("line 6"), std::string::npos) << "step skipped";
    EXPECT_NE(errorOf("5 1.0 2.0\n").find("line 6"), std::string::npos) << "3 fields";
    EXPECT_THROW(loadIcpSlamPath(dir.file("missing.txt"), rawlog), InputError);
    EXPECT_THROW(loadIcpSlamPath(writePath(dir, 6), dir.file("missing.rawlog")), InputError);
}

TEST(IcpSlamPath, TruncatedRawlogIsAnInputError) {
    TempDir dir;
    const std::string rawlog = writeObservationRawlog(dir);
    // Cut the last object in half: MRPT readers (and icp-slam) would stop silently there.
    std::ifstream in(rawlog, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string cut = dir.file("cut.rawlog");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 20);
    EXPECT_THROW(icpSlamStepsOf(cut), InputError);
}
