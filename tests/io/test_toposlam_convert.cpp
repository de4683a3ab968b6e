// toposlam-convert end to end: logs to rawlogs (both formats) and odometry trajectories, grid
// map conversions, bad input (message, exit code, no partial output), and MRPT's own tools
// (rawlog-edit, icp-slam) on the converted mit-csail log.
#include <gtest/gtest.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/Trajectory.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "TestSupport.h"

namespace fs = std::filesystem;
using toposlam::test::runApp;
using toposlam::test::runCommand;
using toposlam::test::TempDir;

namespace {

using toposlam::test::writeText;

using toposlam::test::readFile;

// A CARMEN log of `n` FLASER lines (181 readings) with a robot moving along x, one scan every
// 0.07 s from 9.9 s; scan 2 (10.04 s) is printed as old loggers did, with unpadded
// microseconds: "10.40000", a step backwards before 10.11.
std::string carmenLog(std::size_t n) {
    std::ostringstream s;
    s << "# test log\nPARAM robot_front_laser_max 30.0 nohost 0\n";
    for (std::size_t i = 0; i < n; ++i) {
        const double x = 0.1 * static_cast<double>(i);
        const std::string stamp =
            i == 2 ? "10.40000" : std::to_string(9.9 + 0.07 * static_cast<double>(i));
        s << "ODOM " << x << " 0 0 0.1 0 0 " << stamp << " nohost " << stamp << "\n";
        s << "FLASER 181";
        for (int b = 0; b < 181; ++b)
            s << ' ' << (b == 90 ? 35.0 : 2.0 + 0.01 * b);
        s << ' ' << x << " 0 0 " << x << " 0 0 " << stamp << " nohost " << stamp << "\n";
    }
    return s.str();
}

// Lines of a text file.
std::size_t lineCount(const std::string& path) {
    std::ifstream in(path);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);)
        ++n;
    return n;
}

// Reads the logs `original` and `converted` scan by scan and calls check(i, a, b) on each
// pair; a failure when they do not hold the same number of scans. Returns the pairs read.
std::size_t forEachScanPair(
    const std::string& original, const std::string& converted,
    const std::function<void(std::size_t, const toposlam::io::LaserLogRecord&,
                             const toposlam::io::LaserLogRecord&)>& check) {
    toposlam::io::LaserLogReader before(original), after(converted);
    toposlam::io::LaserLogRecord a, b;
    std::size_t pairs = 0;
    while (before.next(a)) {
        if (!after.next(b)) {
            ADD_FAILURE() << converted << " ends after " << pairs << " scans";
            return pairs;
        }
        check(pairs++, a, b);
    }
    EXPECT_FALSE(after.next(b)) << converted << " has more scans than " << original;
    return pairs;
}

bool haveTool(const std::string& tool) {
    return runCommand("command -v " + tool + " >/dev/null").exitCode == 0;
}

}  // namespace

TEST(ToposlamConvert, CarmenToRawlogInBothFormats) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(5));
    for (const std::string format : {"obs", "sf"}) {
        const std::string out = dir.file("log_" + format + ".rawlog.gz");
        const auto r =
            runApp("toposlam-convert", dir.file("log.clf") + " -o " + out + " --format " + format);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("5 scans of 181 readings"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("10 objects"), std::string::npos) << r.output;
        toposlam::io::LaserLogReader reader(out);
        EXPECT_EQ(reader.format(), format == "sf"
                                       ? toposlam::io::LaserLogFormat::RawlogSensoryFrames
                                       : toposlam::io::LaserLogFormat::RawlogObservations);
        toposlam::io::LaserLogRecord rec;
        std::size_t n = 0;
        while (reader.next(rec)) {
            EXPECT_EQ(rec.scan->maxRange, 30.0f);
            EXPECT_FALSE(rec.scan->getScanRangeValidity(90)) << "35 m >= PARAM max range";
            EXPECT_NEAR(rec.odometry.x(), 0.1 * static_cast<double>(n), 1e-9);
            ++n;
        }
        EXPECT_EQ(n, 5u);
    }
}

TEST(ToposlamConvert, KeepEveryNthScanIsALowerScanRate) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(8));
    const std::string out = dir.file("every3.rawlog");
    const auto r = runApp("toposlam-convert", dir.file("log.clf") + " -o " + out +
                                                  " --keep-every 3 --odometry-trajectory " +
                                                  dir.file("odo.txt"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("3 scans of 181 readings"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("5 scans left out (one kept in 3)"), std::string::npos) << r.output;
    // Scans 0, 3 and 6, each with the odometry at that scan: increments span the left-out ones.
    toposlam::io::LaserLogReader reader(out);
    toposlam::io::LaserLogRecord rec;
    std::vector<double> x;
    while (reader.next(rec))
        x.push_back(rec.odometry.x());
    ASSERT_EQ(x.size(), 3u);
    EXPECT_NEAR(x[1], 0.3, 1e-9);
    EXPECT_NEAR(x[2], 0.6, 1e-9);
    const auto t = toposlam::io::loadTrajectory(dir.file("odo.txt"));
    ASSERT_EQ(t.size(), 3u);
    EXPECT_NEAR(t[1].stamp, 9.9 + 0.21, 1e-9) << "the kept scans' own stamps";
    // --max-scans counts the scans read: the first 4 read keep scans 0 and 3.
    const auto first4 =
        runApp("toposlam-convert", dir.file("log.clf") + " -q -o " + dir.file("first4.rawlog") +
                                       " --keep-every 3 --max-scans 4");
    ASSERT_EQ(first4.exitCode, 0) << first4.output;
    toposlam::io::LaserLogReader first(dir.file("first4.rawlog"));
    std::size_t n = 0;
    while (first.next(rec))
        ++n;
    EXPECT_EQ(n, 2u);
}

// The direction of reading `i` of `scan` in the robot frame (rad).
double beamDirection(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
    const double step = double(scan.aperture) / double(scan.getScanSize() - 1);
    const double inSensor = (scan.rightToLeft ? 1.0 : -1.0) * (-0.5 * scan.aperture + step * i);
    return scan.sensorPose.yaw() + inSensor;
}

TEST(ToposlamConvert, KeepEveryNthBeamIsACoarserLaserPointingTheSameWay) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(3));
    const std::string out = dir.file("beams.rawlog");
    const auto r =
        runApp("toposlam-convert", dir.file("log.clf") + " -o " + out + " --keep-beam-every 4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // 181 readings, 1 deg apart: beams 0, 4, ..., 180 are kept, 4 deg apart, still -90..+90.
    EXPECT_NE(r.output.find("3 scans of 46 readings"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("one beam kept in 4"), std::string::npos) << r.output;
    toposlam::io::LaserLogReader original(dir.file("log.clf")), coarse(out);
    toposlam::io::LaserLogRecord a, b;
    ASSERT_TRUE(original.next(a));
    ASSERT_TRUE(coarse.next(b));
    ASSERT_EQ(b.scan->getScanSize(), 46u);
    for (std::size_t k = 0; k < 46; ++k) {
        EXPECT_FLOAT_EQ(b.scan->getScanRange(k), a.scan->getScanRange(4 * k));
        EXPECT_EQ(b.scan->getScanRangeValidity(k), a.scan->getScanRangeValidity(4 * k));
        EXPECT_NEAR(beamDirection(*b.scan, k), beamDirection(*a.scan, 4 * k), 1e-6);
    }
    // Kept beams that no longer span the fan symmetrically (180 readings, one in 7: the last
    // kept is 5 short of the end) turn the sensor to their centre; either beam order.
    for (const bool rightToLeft : {true, false}) {
        mrpt::obs::CObservation2DRangeScan scan;
        scan.aperture = static_cast<float>(M_PI * 179.0 / 180.0);
        scan.rightToLeft = rightToLeft;
        scan.sensorPose = mrpt::poses::CPose3D(0.1, 0, 0, 0.2, 0, 0);
        scan.resizeScan(180);
        for (std::size_t i = 0; i < 180; ++i) {
            scan.setScanRange(i, 1.0f + 0.01f * static_cast<float>(i));
            scan.setScanRangeValidity(i, i % 5 != 0);
        }
        const auto kept = toposlam::io::keepEveryBeam(scan, 7);
        ASSERT_EQ(kept->getScanSize(), 26u);
        for (std::size_t k = 0; k < 26; ++k) {
            SCOPED_TRACE(k);
            EXPECT_NEAR(beamDirection(*kept, k), beamDirection(scan, 7 * k), 1e-6);
            EXPECT_EQ(kept->getScanRangeValidity(k), scan.getScanRangeValidity(7 * k));
        }
    }
}

TEST(ToposlamConvert, ClipRangeIsALaserThatSeesLessFar) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(2));  // readings 2.00 .. 3.80 m, one at 35 m
    const std::string out = dir.file("short.rawlog");
    const auto r =
        runApp("toposlam-convert", dir.file("log.clf") + " -o " + out + " --clip-range 3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("readings from 3.00 m on invalid"), std::string::npos) << r.output;
    toposlam::io::LaserLogReader original(dir.file("log.clf")), clipped(out);
    toposlam::io::LaserLogRecord a, b;
    ASSERT_TRUE(original.next(a));
    ASSERT_TRUE(clipped.next(b));
    ASSERT_EQ(b.scan->getScanSize(), a.scan->getScanSize());
    EXPECT_FLOAT_EQ(b.scan->maxRange, 3.0f);
    std::size_t valid = 0;
    for (std::size_t i = 0; i < a.scan->getScanSize(); ++i) {
        const bool near = a.scan->getScanRangeValidity(i) && a.scan->getScanRange(i) < 3.0f;
        EXPECT_EQ(b.scan->getScanRangeValidity(i), near) << i;
        valid += near;
    }
    EXPECT_EQ(valid, 99u);  // 2.00 .. 2.99 m but the 35 m reading among them
}

TEST(ToposlamConvert, MirrorIsTheLogsMirrorImage) {
    // A robot turning left along an arc: in the mirror image it turns right, every scan reversed.
    std::ostringstream log;
    log << "PARAM robot_front_laser_max 30.0 nohost 0\n";
    for (int i = 0; i < 4; ++i) {
        const double x = 0.1 * i, y = 0.02 * i * i, yaw = 0.1 * i, stamp = 5.0 + 0.1 * i;
        log << "FLASER 181";
        for (int b = 0; b < 181; ++b)
            log << ' ' << 2.0 + 0.01 * b + 0.1 * i;
        log << ' ' << x << ' ' << y << ' ' << yaw << ' ' << x << ' ' << y << ' ' << yaw << ' '
            << stamp << " nohost " << stamp << "\n";
    }
    TempDir dir;
    writeText(dir.file("log.clf"), log.str());
    const std::string out = dir.file("mirrored.rawlog"), odometry = dir.file("odo.txt");
    const auto r = runApp("toposlam-convert", dir.file("log.clf") + " -o " + out +
                                                  " --mirror --odometry-trajectory " + odometry);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("mirrored (left and right swapped)"), std::string::npos) << r.output;
    using Record = toposlam::io::LaserLogRecord;
    const std::size_t scans = forEachScanPair(
        dir.file("log.clf"), out, [](std::size_t, const Record& a, const Record& b) {
            EXPECT_EQ(b.fileStamp, a.fileStamp);
            EXPECT_NEAR(b.odometry.x(), a.odometry.x(), 1e-9);
            EXPECT_NEAR(b.odometry.y(), -a.odometry.y(), 1e-9);
            EXPECT_NEAR(b.odometry.phi(), -a.odometry.phi(), 1e-9);
            EXPECT_NEAR(b.scan->sensorPose.yaw(), -a.scan->sensorPose.yaw(), 1e-9);
            const std::size_t n = a.scan->getScanSize();
            ASSERT_EQ(b.scan->getScanSize(), n);
            for (std::size_t i = 0; i < n; ++i)
                EXPECT_EQ(b.scan->getScanRange(i), a.scan->getScanRange(n - 1 - i)) << i;
        });
    EXPECT_EQ(scans, 4u);
    const auto t = toposlam::io::loadTrajectory(odometry);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_NEAR(t[3].pose.y, -0.18, 1e-9);
    EXPECT_NEAR(t[3].pose.phi, -0.3, 1e-9);
}

TEST(ToposlamConvert, NoOdometryIsALaserOnlyLogInBothFormats) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(4));
    for (const std::string format : {"obs", "sf"}) {
        SCOPED_TRACE(format);
        const std::string out = dir.file("laser-only-" + format + ".rawlog");
        const auto r = runApp("toposlam-convert", dir.file("log.clf") + " -o " + out +
                                                      " --no-odometry --format " + format);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("odometry left out"), std::string::npos) << r.output;
        // The same scans, none with odometry (sf: no action, not a zero increment).
        using Record = toposlam::io::LaserLogRecord;
        const std::size_t scans = forEachScanPair(
            dir.file("log.clf"), out, [](std::size_t i, const Record& a, const Record& b) {
                EXPECT_TRUE(a.hasOdometry);
                EXPECT_FALSE(b.hasOdometry) << "scan " << i;
                EXPECT_EQ(b.scan->getScanSize(), a.scan->getScanSize());
                EXPECT_EQ(b.scan->getScanRange(0), a.scan->getScanRange(0));
            });
        EXPECT_EQ(scans, 4u);
    }
    // Nothing would be left for an odometry trajectory.
    const auto r = runApp("toposlam-convert", dir.file("log.clf") + " -o " + dir.file("x.rawlog") +
                                                  " --no-odometry " + "--odometry-trajectory " +
                                                  dir.file("odo.txt"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--no-odometry"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("x.rawlog")));
}

TEST(ToposlamConvert, OdometryTrajectoryUsesPrintedStamps) {
    TempDir dir;
    writeText(dir.file("log.clf"), carmenLog(4));
    const auto r = runApp("toposlam-convert",
                          dir.file("log.clf") + " --odometry-trajectory " + dir.file("odo.txt"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("1 timestamps repaired"), std::string::npos) << r.output;
    const auto t = toposlam::io::loadTrajectory(dir.file("odo.txt"));
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[2].stamp, 10.4) << "the stamp as printed, not the repaired time";
    EXPECT_EQ(t[3].pose.x, 0.3);
    const std::string text = readFile(dir.file("odo.txt"));
    EXPECT_NE(text.find("\n10.4 0.2 0 0\n"), std::string::npos) << text;
}

TEST(ToposlamConvert, BadLogsFailCleanly) {
    TempDir dir;
    // Missing input.
    auto r = runApp("toposlam-convert", dir.file("none.clf") + " -o " + dir.file("out.rawlog"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("error: " + dir.file("none.clf") + ": file not found"),
              std::string::npos)
        << r.output;

    // A NaN reading on line 7: no rawlog, no trajectory.
    std::string log = carmenLog(4);
    const auto pos = log.find(" 2.01 ", log.rfind("FLASER"));
    log.replace(pos, 6, " nan ");
    writeText(dir.file("nan.clf"), log);
    r = runApp("toposlam-convert", dir.file("nan.clf") + " -o " + dir.file("out.rawlog") +
                                       " --odometry-trajectory " + dir.file("odo.txt"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("nan.clf: line 10: reading 1 is nan"), std::string::npos) << r.output;

    // Wrong field count.
    writeText(dir.file("short.clf"), "FLASER 3 1 2 0 0 0 0 0 0 1.0 nohost 1.0\n");
    r = runApp("toposlam-convert", dir.file("short.clf") + " -o " + dir.file("out.rawlog"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("line 1: FLASER has 13 fields, expected 14"), std::string::npos)
        << r.output;

    // A truncated rawlog.
    writeText(dir.file("ok.clf"), carmenLog(20));
    ASSERT_EQ(
        runApp("toposlam-convert", dir.file("ok.clf") + " -q -o " + dir.file("ok.rawlog")).exitCode,
        0);
    std::string bytes = readFile(dir.file("ok.rawlog"));
    fs::remove(dir.file("ok.rawlog"));
    // All records have the same size: cut inside one (a cut exactly between two objects
    // cannot be told from the end of a plain rawlog).
    std::ofstream(dir.file("cut.rawlog"), std::ios::binary)
        << bytes.substr(0, bytes.size() / 2 + 100);
    r = runApp("toposlam-convert", dir.file("cut.rawlog") + " -o " + dir.file("out.rawlog.gz"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("cut.rawlog: object #"), std::string::npos) << r.output;

    // No scan with the requested label.
    r = runApp("toposlam-convert",
               dir.file("ok.clf") + " --label RLASER -o " + dir.file("out.rawlog"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("no laser scans labelled 'RLASER' in the log (it has FLASER: "),
              std::string::npos)
        << r.output;

    // Bad options: bad usage, exit status 2.
    r = runApp("toposlam-convert", dir.file("ok.clf") + " --format xyz -o " + dir.file("o.rawlog"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
    r = runApp("toposlam-convert", dir.file("ok.clf"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("nothing to do"), std::string::npos) << r.output;
    r = runApp("toposlam-convert",
               dir.file("ok.clf") + " --laser-offset 1,2 -o " + dir.file("o.rawlog"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--laser-offset"), std::string::npos) << r.output;

    for (const auto& e : fs::directory_iterator(dir.path())) {
        const std::string name = e.path().filename().string();
        EXPECT_TRUE(name.find(".clf") != std::string::npos || name == "cut.rawlog")
            << "left behind: " << name;
    }
}

TEST(ToposlamConvert, GridMapsBetweenFormats) {
    TempDir dir;
    mrpt::maps::COccupancyGridMap2D g(-2.0f, 3.0f, -1.0f, 1.5f, 0.1f);
    g.fill(0.95f);
    for (int cx = 0; cx < static_cast<int>(g.getSizeX()); ++cx)
        g.setCell(cx, 0, 0.05f);
    toposlam::io::saveGridMap(g, dir.file("a.gridmap.gz"));

    auto r = runApp("toposlam-convert", dir.file("a.gridmap.gz") + " -o " + dir.file("b.yaml"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("50 x 25 cells"), std::string::npos) << r.output;
    r = runApp("toposlam-convert", dir.file("b.yaml") + " -o " + dir.file("c.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runApp("toposlam-convert", dir.file("c.png") + " -o " + dir.file("d.gridmap"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto d = toposlam::io::loadGridMap(dir.file("d.gridmap"));
    EXPECT_EQ(d.getSizeX(), 50u);
    EXPECT_EQ(d.getXMin(), -2.0f);
    EXPECT_EQ(d.getYMin(), -1.0f);
    EXPECT_LT(d.getCell(10, 0), 0.1f);
    EXPECT_GT(d.getCell(10, 1), 0.9f);

    // A bare image placed by the options.
    fs::remove(dir.file("c.yaml"));
    r = runApp("toposlam-convert",
               dir.file("c.png") + " --resolution 0.2 --origin 5,-5 -o " + dir.file("e.gridmap"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto e = toposlam::io::loadGridMap(dir.file("e.gridmap"));
    EXPECT_EQ(e.getResolution(), 0.2f);
    EXPECT_EQ(e.getXMin(), 5.0f);
    EXPECT_EQ(e.getYMax(), 0.0f);
}

TEST(ToposlamConvert, AResolutionOrOriginAloneKeepsTheSidecarsOtherValues) {
    TempDir dir;
    const std::string office = toposlam::test::shareDir() + "/office/";
    for (const char* f : {"office.png", "office.yaml", "office.pgm"})
        fs::copy_file(office + f, dir.file(f));
    const auto asItIs = toposlam::io::loadGridMap(dir.file("office.png"));
    auto r = runApp("toposlam-convert", "'" + dir.file("office.png") + "' --resolution 0.1 -o '" +
                                            dir.file("scaled.gridmap") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto scaled = toposlam::io::loadGridMap(dir.file("scaled.gridmap"));
    EXPECT_EQ(scaled.getResolution(), 0.1f);
    EXPECT_FLOAT_EQ(scaled.getXMin(), -0.7f) << "the sidecar's origin, not (0,0)";
    EXPECT_FLOAT_EQ(scaled.getYMin(), -0.7f);
    EXPECT_EQ(toposlam::io::countFreeCells(scaled), toposlam::io::countFreeCells(asItIs))
        << "read as the sidecar says (a grid), not as a drawn plan";
    r = runApp("toposlam-convert", "'" + dir.file("office.png") + "' --origin 1,2 -o '" +
                                       dir.file("moved.gridmap") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto moved = toposlam::io::loadGridMap(dir.file("moved.gridmap"));
    EXPECT_EQ(moved.getResolution(), asItIs.getResolution());
    EXPECT_FLOAT_EQ(moved.getXMin(), 1.0f);
    EXPECT_FLOAT_EQ(moved.getYMin(), 2.0f);
}

TEST(ToposlamConvert, ABarePlanPictureBecomesAGridWithItsGreyWallsOccupied) {
    // A white room behind light-grey walls (211, p(free) 0.83) in a grey background (180):
    // read as the drawn plan it is, the walls and the background are written occupied; read
    // as a grid (--grid) they stay as light as they are, and a grid reader takes the walls for
    // free space.
    TempDir dir;
    cv::Mat plan(40, 60, CV_8U, cv::Scalar(180));
    plan(cv::Rect(10, 10, 40, 20)).setTo(211);
    plan(cv::Rect(12, 12, 36, 16)).setTo(255);
    ASSERT_TRUE(cv::imwrite(dir.file("plan.png"), plan));
    auto r = runApp("toposlam-convert", dir.file("plan.png") + " -o " + dir.file("plan.gridmap"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("read as a drawn floor plan"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(std::to_string(36 * 16) + " free cells"), std::string::npos)
        << r.output;
    const auto drawn = toposlam::io::loadGridMap(dir.file("plan.gridmap"));
    // Image row 0 is the top: cell (x, 39 - row).
    EXPECT_LT(drawn.getCell(11, 20), 0.01f) << "wall";
    EXPECT_LT(drawn.getCell(2, 2), 0.01f) << "background";
    EXPECT_GT(drawn.getCell(30, 20), 0.98f) << "room";
    r = runApp("toposlam-convert", dir.file("plan.png") + " --grid -o " + dir.file("grid.gridmap"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto grid = toposlam::io::loadGridMap(dir.file("grid.gridmap"));
    EXPECT_NEAR(grid.getCell(11, 20), 211 / 255.0, 0.02) << "wall, as light as drawn";
    // The two readings are for maps only.
    r = runApp("toposlam-convert", toposlam::test::shareDir() +
                                       "/office/office.rawlog --drawn -o " + dir.file("x.rawlog"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--drawn, --grid, --resolution and --origin are for grid maps"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir.file("x.rawlog")));
    r = runApp("toposlam-convert", toposlam::test::shareDir() +
                                       "/office/office.rawlog --resolution 0.1 -o " +
                                       dir.file("x.rawlog"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("x.rawlog")));
    // And the log options are for logs only: on a map they would be ignored.
    for (const char* option :
         {"--label FLASER", "--format sf", "--max-scans 3", "--keep-every 2"}) {
        r = runApp("toposlam-convert",
                   dir.file("plan.png") + " " + option + " -o " + dir.file("y.gridmap"));
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.output;
        EXPECT_NE(r.output.find(" is for laser logs, not grid maps"), std::string::npos)
            << r.output;
    }
    EXPECT_FALSE(fs::exists(dir.file("y.gridmap")));
}

TEST(ToposlamConvert, BadMapsFailCleanly) {
    TempDir dir;
    mrpt::maps::COccupancyGridMap2D walls(0, 1, 0, 1, 0.1f);
    walls.fill(0.0f);
    toposlam::io::saveGridMap(walls, dir.file("walls.gridmap"));
    auto r = runApp("toposlam-convert", dir.file("walls.gridmap") + " -o " + dir.file("w.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("error: " + dir.file("walls.gridmap") + ": map has no free cells"),
              std::string::npos)
        << r.output;
    writeText(dir.file("broken.png"), "not an image");
    r = runApp("toposlam-convert", dir.file("broken.png") + " -o " + dir.file("b.gridmap"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("broken.png: cannot read the image"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("w.png")));
    EXPECT_FALSE(fs::exists(dir.file("w.yaml")));
    EXPECT_FALSE(fs::exists(dir.file("b.gridmap")));
}

// The converted mit-csail log with MRPT's own tools: rawlog-edit must count 2 x 1988 objects
// and see every scan's and every odometry's timestamp distinct and increasing (an odometry
// shares its scan's time); icp-slam must run and log one pose per rawlog entry. icp-slam runs
// on the first 500 scans only (the full log takes ~40 s).
TEST(ToposlamConvert, MitCsailWithMrptTools) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(clf, "slam/mit-csail.clf");
    if (!haveTool("rawlog-edit") || !haveTool("icp-slam")) {
        GTEST_SKIP() << "MRPT apps (package mrpt-apps) not installed";
    }
    TempDir dir;
    auto r = runApp("toposlam-convert", clf + " -q -o " + dir.file("mit.rawlog"));
    ASSERT_EQ(r.exitCode, 0) << r.output;

    r = runCommand("rawlog-edit -i " + dir.file("mit.rawlog") + " --info");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Overall number of objects         : 3976"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("Observations format               : Yes"), std::string::npos);

    r = runCommand("rawlog-edit -i " + dir.file("mit.rawlog") +
                   " --list-timestamps --text-file-output " + dir.file("stamps.txt"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir.file("stamps.txt"));
    std::map<std::string, std::vector<double>> stampsByLabel;
    double t = 0;
    std::string label, cls;
    while (in >> t >> label >> cls)
        stampsByLabel[label].push_back(t);
    ASSERT_EQ(stampsByLabel["FLASER"].size(), 1988u);
    ASSERT_EQ(stampsByLabel["ODOMETRY"].size(), 1988u);
    for (const auto& [name, stamps] : stampsByLabel) {
        for (std::size_t i = 1; i < stamps.size(); ++i) {
            ASSERT_GT(stamps[i], stamps[i - 1]) << name << " " << i;
        }
    }

    r = runApp("toposlam-convert", clf + " -q --max-scans 500 -o " + dir.file("mit500.rawlog"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::string ini = readFile(std::string(TOPOSLAM_CONFIG_DIR) + "/icp-slam-carmen.ini");
    const std::string key = "logOutput_dir = icp-slam-out";
    ASSERT_NE(ini.find(key), std::string::npos);
    ini.replace(ini.find(key), key.size(), "logOutput_dir = " + dir.file("icp"));
    writeText(dir.file("icp.ini"), ini);
    r = runCommand("cd " + dir.path() + " && icp-slam icp.ini mit500.rawlog");
    ASSERT_EQ(r.exitCode, 0) << r.output.substr(r.output.size() > 2000 ? r.output.size() - 2000
                                                                       : 0);
    EXPECT_EQ(lineCount(dir.file("icp/log_estimated_path.txt")), 1000u);
}
