// LaserLogReader on CARMEN logs: beam geometry, ranges, laser offsets, timestamps, bad input;
// and on the benchmark logs when ../shared/data is present.
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <toposlam/io/CarmenTimestamps.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "LogReadError.h"
#include "TestSupport.h"

using namespace toposlam::io;

namespace {

constexpr double kDeg = M_PI / 180.0;

using toposlam::test::writeText;

// "FLASER n r... x y theta odom_x odom_y odom_theta stamp host logger_stamp"
std::string flaser(std::size_t n, double range, const std::string& laserPose,
                   const std::string& robotPose, const std::string& stamp,
                   const std::string& name = "FLASER") {
    std::ostringstream s;
    s << name << ' ' << n;
    for (std::size_t i = 0; i < n; ++i)
        s << ' ' << range;
    s << ' ' << laserPose << ' ' << robotPose << ' ' << stamp << " nohost " << stamp << '\n';
    return s.str();
}

// Direction of reading i in the robot frame (rad): MRPT's beam angle plus the sensor yaw.
double beamDirection(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
    return scan.getScanAngle(i) + scan.sensorPose.yaw();
}

using toposlam::test::logReadError;

}  // namespace

TEST(CarmenReader, OldFormatBeamLayoutFollowsCarmen) {
    toposlam::test::TempDir dir;
    // 180 readings: -90..+89 deg at 1 deg; 360: -90..+89.5 at 0.5 deg; 361: -90..+90.
    const std::string log = flaser(180, 2.0, "0 0 0", "0 0 0", "1.000000") +
                            flaser(360, 2.0, "0 0 0", "0 0 0", "2.000000") +
                            flaser(361, 2.0, "0 0 0", "0 0 0", "3.000000");
    writeText(dir.file("a.clf"), log);
    LaserLogReader reader(dir.file("a.clf"));
    EXPECT_EQ(reader.format(), LaserLogFormat::Carmen);
    const struct {
        std::size_t n;
        double stepDeg;
    } expected[] = {{180, 1.0}, {360, 0.5}, {361, 0.5}};
    for (const auto& e : expected) {
        LaserLogRecord r;
        ASSERT_TRUE(reader.next(r));
        ASSERT_EQ(r.scan->getScanSize(), e.n);
        // 1e-6 rad: float aperture and angles.
        EXPECT_NEAR(r.scan->aperture, (e.n - 1) * e.stepDeg * kDeg, 1e-6);
        for (std::size_t i = 0; i < e.n; ++i) {
            ASSERT_NEAR(beamDirection(*r.scan, i), (-90.0 + i * e.stepDeg) * kDeg, 1e-5)
                << e.n << " readings, beam " << i;
        }
        EXPECT_TRUE(r.scan->rightToLeft);
        EXPECT_EQ(r.scan->sensorLabel, "FLASER");
    }
}

TEST(CarmenReader, OneLaserKeepsTheFrontLaserAndCountsTheOthers) {
    toposlam::test::TempDir dir;
    // The rear laser's line comes first; the front one is still the one kept.
    const std::string log = flaser(180, 1.0, "0 0 0", "0 0 0", "1.0", "RLASER") +
                            flaser(180, 2.0, "0 0 0", "0 0 0", "1.1") +
                            flaser(180, 1.0, "0 0 0", "0 0 0", "1.2", "RLASER") +
                            flaser(180, 2.0, "0 0 0", "0 0 0", "1.3");
    writeText(dir.file("two.clf"), log);
    EXPECT_EQ(LaserLogReader::readAll(dir.file("two.clf")).size(), 4u) << "default: every scan";
    LaserLogOptions one;
    one.oneLaser = true;
    LaserLogReader reader(dir.file("two.clf"), one);
    EXPECT_EQ(reader.laserLabel(), "FLASER") << "known before the first scan";
    LaserLogRecord r;
    std::vector<double> stamps;
    while (reader.next(r)) {
        EXPECT_EQ(r.scan->sensorLabel, "FLASER");
        EXPECT_EQ(r.index, stamps.size()) << "indices count the scans kept";
        stamps.push_back(r.fileStamp);
    }
    EXPECT_EQ(stamps, (std::vector<double>{1.1, 1.3}));
    EXPECT_EQ(reader.otherLaserScans(), (std::map<std::string, std::size_t>{{"RLASER", 2}}));
    // A label given wins over oneLaser.
    one.scanLabel = "RLASER";
    const auto rear = LaserLogReader::readAll(dir.file("two.clf"), one);
    ASSERT_EQ(rear.size(), 2u);
    EXPECT_EQ(rear[0].scan->sensorLabel, "RLASER");
    // Only a rear laser: that one.
    writeText(dir.file("rear.clf"), flaser(180, 1.0, "0 0 0", "0 0 0", "1.0", "RLASER"));
    one.scanLabel.clear();
    LaserLogReader onlyRear(dir.file("rear.clf"), one);
    EXPECT_TRUE(onlyRear.next(r));
    EXPECT_EQ(onlyRear.laserLabel(), "RLASER");
    EXPECT_TRUE(onlyRear.otherLaserScans().empty());
}

TEST(CarmenReader, ParamResolutionMaxRangeAndOffset) {
    toposlam::test::TempDir dir;
    std::string log =
        "# comment\n"
        "PARAM laser_front_laser_resolution 0.5 nohost 0\n"
        "PARAM robot_front_laser_max 50.0 nohost 0\n"
        "PARAM robot_frontlaser_offset 0.25 nohost 0\n"
        "PARAM robot_use_rear_laser off nohost 0\n";
    std::ostringstream line;
    line << "FLASER 180";
    for (int i = 0; i < 180; ++i)
        line << ' ' << (i == 0 ? 0.0 : i == 1 ? 50.0 : i == 2 ? 49.99 : 3.0);
    line << " 1 2 0.5 1 2 0.5 10.5 nohost 10.5\n";
    log += line.str();
    writeText(dir.file("p.clf"), log);
    const auto records = LaserLogReader::readAll(dir.file("p.clf"));
    ASSERT_EQ(records.size(), 1u);
    const auto& scan = *records[0].scan;
    EXPECT_EQ(scan.maxRange, 50.0f);
    EXPECT_FALSE(scan.getScanRangeValidity(0)) << "0 = no return";
    EXPECT_FALSE(scan.getScanRangeValidity(1)) << ">= max range";
    EXPECT_TRUE(scan.getScanRangeValidity(2));
    EXPECT_TRUE(scan.getScanRangeValidity(3));
    // PARAM resolution 0.5 deg with 180 readings: 89.5 deg, not ~180: centred.
    EXPECT_NEAR(scan.aperture, 179 * 0.5 * kDeg, 1e-6);
    EXPECT_NEAR(beamDirection(scan, 0), -44.75 * kDeg, 1e-5);
    EXPECT_NEAR(scan.sensorPose.x(), 0.25, 1e-12) << "PARAM offset: the line states none";
    EXPECT_EQ(records[0].odometry, mrpt::poses::CPose2D(1, 2, 0.5));
    EXPECT_TRUE(records[0].hasOdometry);
    EXPECT_EQ(records[0].fileStamp, 10.5);
}

TEST(CarmenReader, LaserPoseStatedInTheLineWins) {
    toposlam::test::TempDir dir;
    // Robot at (1, 2, 90 deg), laser 0.22 m ahead of it: (1, 2.22).
    const std::string log =
        "PARAM robot_frontlaser_offset 0.5\n" +
        flaser(181, 3.0, "1 2.22 1.5707963267948966", "1 2 1.5707963267948966", "5.000000") +
        // A "laser pose" 30 m away: a corrected estimate, not a mount.
        flaser(181, 3.0, "31 2 0", "1 2 0", "6.000000");
    writeText(dir.file("o.clf"), log);
    const auto records = LaserLogReader::readAll(dir.file("o.clf"));
    ASSERT_EQ(records.size(), 2u);
    EXPECT_NEAR(records[0].scan->sensorPose.x(), 0.22, 1e-9);
    EXPECT_NEAR(records[0].scan->sensorPose.y(), 0.0, 1e-9);
    EXPECT_NEAR(records[0].scan->sensorPose.yaw(), 0.0, 1e-9);
    EXPECT_NEAR(records[1].scan->sensorPose.x(), 0.5, 1e-9) << "falls back to PARAM";
    // Override.
    LaserLogOptions options;
    options.laserPoseOnRobot = mrpt::math::TPose2D(0.04, 0, 0);
    const auto overridden = LaserLogReader::readAll(dir.file("o.clf"), options);
    EXPECT_NEAR(overridden[0].scan->sensorPose.x(), 0.04, 1e-12);
}

TEST(CarmenReader, RobotLaserStatesItsGeometry) {
    toposlam::test::TempDir dir;
    // 5 readings from -60 deg in 30 deg steps, max 8 m, 2 remission values, laser 0.22 m
    // ahead of the robot at (3, 4, 0).
    const std::string line =
        "ROBOTLASER1 0 -1.0471975511965976 2.0943951023931953 0.5235987755982988 8.0 0.01 0 "
        "5 1.0 2.0 8.0 9.5 0.0 2 0.1 0.2 3.22 4 0 3 4 0 0.1 0.0 0.5 0.3 0.0 "
        "100.250000 host 100.25\n";
    writeText(dir.file("r.clf"), line);
    const auto records = LaserLogReader::readAll(dir.file("r.clf"));
    ASSERT_EQ(records.size(), 1u);
    const auto& scan = *records[0].scan;
    EXPECT_EQ(scan.sensorLabel, "ROBOTLASER1");
    EXPECT_EQ(scan.maxRange, 8.0f);
    EXPECT_NEAR(scan.sensorPose.x(), 0.22, 1e-9);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(beamDirection(scan, i), (-60.0 + 30.0 * i) * kDeg, 1e-6);
    }
    EXPECT_TRUE(scan.getScanRangeValidity(1));
    EXPECT_FALSE(scan.getScanRangeValidity(2)) << "8.0 >= max range";
    EXPECT_FALSE(scan.getScanRangeValidity(3)) << "9.5 >= max range";
    EXPECT_FALSE(scan.getScanRangeValidity(4)) << "0 = no return";
    EXPECT_EQ(records[0].odometry, mrpt::poses::CPose2D(3, 4, 0));
    EXPECT_EQ(records[0].fileStamp, 100.25);
}

// "RAWLASERk laser_type start fov resolution max accuracy remission_mode n r... 0 stamp host
// logger_stamp": 5 readings from -60 deg in 30 deg steps, max 8 m, no remission values.
std::string rawlaser(const std::string& stamp, const std::string& name = "RAWLASER1") {
    return name +
           " 0 -1.0471975511965976 2.0943951023931953 0.5235987755982988 8.0 0.01 0 "
           "5 1.0 2.0 8.0 9.5 0.0 0 " +
           stamp + " host " + stamp + "\n";
}

TEST(CarmenReader, RawLaserScansTakeTheOdometryOfTheOdomLinesAtTheirTime) {
    toposlam::test::TempDir dir;
    // A raw log (CARMEN's laser and base modules, no robot module): RAWLASER and ODOM lines.
    // The ODOM line after a scan is needed to place it: the reader looks ahead.
    const std::string log =
        "PARAM robot_frontlaser_offset 0.1 nohost 0\n"
        "PARAM robot_rearlaser_offset -0.2 nohost 0\n" +
        rawlaser("0.500000") +  // before the first odometry: none
        "ODOM 0 0 0 0 0 0 1.000000 nohost 1.000000\n" + rawlaser("1.500000") +
        rawlaser("1.600000", "RAWLASER2") + "ODOM 1 0 0.2 0 0 0 2.000000 nohost 2.000000\n" +
        "ODOM 1 1 0.2 0 0 0 3.000000 nohost 3.000000\n" +
        rawlaser("3.500000");  // after the last: held
    writeText(dir.file("raw.log"), log);
    const auto records = LaserLogReader::readAll(dir.file("raw.log"));
    ASSERT_EQ(records.size(), 4u);
    EXPECT_FALSE(records[0].hasOdometry);
    ASSERT_TRUE(records[1].hasOdometry);
    // Half way from (0, 0, 0) to (1, 0, 0.2) in the first sample's frame.
    EXPECT_NEAR(records[1].odometry.x(), 0.5, 1e-12);
    EXPECT_NEAR(records[1].odometry.y(), 0.0, 1e-12);
    EXPECT_NEAR(records[1].odometry.phi(), 0.1, 1e-12);
    EXPECT_NEAR(records[2].odometry.x(), 0.6, 1e-12);
    ASSERT_TRUE(records[3].hasOdometry);
    EXPECT_NEAR(records[3].odometry.y(), 1.0, 1e-12);
    EXPECT_NEAR(records[3].odometry.phi(), 0.2, 1e-12);
    EXPECT_EQ(records[1].fileStamp, 1.5);

    const auto& front = *records[1].scan;
    EXPECT_EQ(front.sensorLabel, "RAWLASER1");
    EXPECT_EQ(front.maxRange, 8.0f);
    EXPECT_NEAR(front.sensorPose.x(), 0.1, 1e-12) << "PARAM offset: the line states no mount";
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(beamDirection(front, i), (-60.0 + 30.0 * i) * kDeg, 1e-6);
    }
    EXPECT_TRUE(front.getScanRangeValidity(1));
    EXPECT_FALSE(front.getScanRangeValidity(2)) << "8.0 >= max range";
    EXPECT_FALSE(front.getScanRangeValidity(4)) << "0 = no return";
    // The second laser is the rear one: PARAM's rear offset, facing backwards.
    const auto& rear = *records[2].scan;
    EXPECT_EQ(rear.sensorLabel, "RAWLASER2");
    EXPECT_NEAR(rear.sensorPose.x(), -0.2, 1e-12);
    EXPECT_NEAR(std::remainder(beamDirection(rear, 2) - M_PI, 2 * M_PI), 0.0, 1e-6);

    LaserLogOptions one;
    one.oneLaser = true;
    LaserLogReader reader(dir.file("raw.log"), one);
    EXPECT_EQ(reader.laserLabel(), "RAWLASER1") << "the front laser";
}

TEST(CarmenReader, RawLaserLinesAreLeftOutWhereLaserLinesStateThePose) {
    toposlam::test::TempDir dir;
    // CARMEN logs of a robot module have both: the FLASER lines carry the synchronised
    // odometry, the RAWLASER lines repeat the scans.
    const std::string log = rawlaser("0.900000") + flaser(180, 2.0, "0 0 0", "0 0 0", "1.0") +
                            rawlaser("1.100000") + "ODOM 0 0 0 0 0 0 1.2 nohost 1.2\n" +
                            flaser(180, 2.0, "0 0 0", "1 0 0", "1.3");
    writeText(dir.file("both.clf"), log);
    const auto records = LaserLogReader::readAll(dir.file("both.clf"));
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].scan->sensorLabel, "FLASER");
    EXPECT_EQ(records[1].odometry, mrpt::poses::CPose2D(1, 0, 0));
}

TEST(CarmenReader, BadLinesNameTheLine) {
    toposlam::test::TempDir dir;
    const std::string good = flaser(180, 2.0, "0 0 0", "0 0 0", "1.000000");
    std::string missing = flaser(180, 2.0, "0 0 0", "0 0 0", "2.000000");
    missing.erase(missing.find(" 2 2 2"), 2);  // one reading less
    writeText(dir.file("count.clf"), good + missing);
    EXPECT_NE(logReadError(dir.file("count.clf"))
                  .find("count.clf: line 2: FLASER has 190 fields, "
                        "expected 191"),
              std::string::npos)
        << logReadError(dir.file("count.clf"));

    std::string nan = good;
    nan.replace(nan.find(" 2 "), 3, " nan ");
    writeText(dir.file("nan.clf"), good + nan);
    EXPECT_NE(logReadError(dir.file("nan.clf")).find("line 2: reading 0 is nan"),
              std::string::npos);

    std::string negative = good;
    negative.replace(negative.find(" 2 2 "), 5, " 2 -0.5 ");
    writeText(dir.file("neg.clf"), "# c\n" + negative);
    EXPECT_NE(logReadError(dir.file("neg.clf")).find("line 2: reading 1 is negative (-0.5)"),
              std::string::npos)
        << logReadError(dir.file("neg.clf"));

    writeText(dir.file("word.clf"), "FLASER 3 1 2 x 0 0 0 0 0 0 1.0 h 1.0\n");
    EXPECT_NE(logReadError(dir.file("word.clf")).find("line 1: reading 2 is not a number: 'x'"),
              std::string::npos);

    writeText(dir.file("odom.clf"), good + "ODOM 1 2 3 0 0 1.5 nohost 1.5\n");
    EXPECT_NE(logReadError(dir.file("odom.clf")).find("line 2: ODOM has 9 fields, expected 10"),
              std::string::npos);

    std::string shortRaw = rawlaser("1.000000");
    shortRaw.erase(shortRaw.find(" 9.5"), 4);  // one reading less
    writeText(dir.file("raw.log"), "ODOM 0 0 0 0 0 0 0.5 nohost 0.5\n" + shortRaw);
    EXPECT_NE(
        logReadError(dir.file("raw.log")).find("line 2: number of remission values is not a count"),
        std::string::npos)
        << logReadError(dir.file("raw.log"));

    writeText(dir.file("text.txt"), "hello world\nthis is text\n");
    EXPECT_NE(logReadError(dir.file("text.txt")).find("not a CARMEN log"), std::string::npos);

    // A file cut in the middle of a line.
    const std::string two = good + good;
    writeText(dir.file("cut.clf"), two.substr(0, two.size() - 40));
    EXPECT_NE(logReadError(dir.file("cut.clf")).find("cut.clf: line 2: FLASER has"),
              std::string::npos);
}

TEST(CarmenTimestamps, CandidatesReadUnpaddedMicroseconds) {
    const auto c = carmenStampCandidates("976052862.228180");
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0], 976052862.228180);
    EXPECT_NEAR(c[1], 976052862.022818, 1e-6);
    const auto original = carmenStampCandidates("12.34567");  // as an old logger printed it
    ASSERT_EQ(original.size(), 2u);
    EXPECT_NEAR(original[1], 12.034567, 1e-9);
    EXPECT_EQ(carmenStampCandidates("12.045670").size(), 1u) << "leading zero: padded";
    EXPECT_EQ(carmenStampCandidates("12.345678").size(), 1u) << "six digits: unambiguous";
    EXPECT_EQ(carmenStampCandidates("12.300000").size(), 6u);
    EXPECT_TRUE(carmenStampCandidates("abc").empty());
}

TEST(CarmenTimestamps, RepairExplainsStepsBackwards) {
    // From intel.clf (scans 146-149): two unpadded stamps in a row, then one step back that
    // no reading explains (scan 12363), then a duplicate.
    const std::vector<std::string_view> printed = {
        "976052885.684386", "976052886.316190", "976052886.542630",
        "976052886.244913", "976052886.581875", "976055298.954832",
        "976055298.250000", "976055299.460398", "976055299.460398"};
    const auto repair = repairCarmenTimestamps(printed);
    ASSERT_EQ(repair.times.size(), printed.size());
    EXPECT_NEAR(repair.times[1], 976052886.031619, 1e-6);
    EXPECT_NEAR(repair.times[2], 976052886.054263, 1e-6);
    EXPECT_EQ(repair.times[3], 976052886.244913);
    EXPECT_EQ(repair.reinterpreted, 2u);
    EXPECT_EQ(repair.forced, 2u);
    EXPECT_NEAR(repair.times[6], 976055298.954832 + 1e-6, 1e-7);
    for (std::size_t i = 1; i < repair.times.size(); ++i)
        EXPECT_GT(repair.times[i], repair.times[i - 1]);
}

TEST(CarmenBenchmark, IntelTimestampsAndRelations) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(clf, "slam/intel.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/intel.relations");
    LaserLogReader reader(clf);
    std::set<std::string> fileStamps;  // printed with 6 decimals, as in the file
    LaserLogRecord r, previous;
    std::size_t n = 0;
    std::size_t stepsBack = 0;
    while (reader.next(r)) {
        if (n > 0) {
            ASSERT_GT(r.scan->timestamp, previous.scan->timestamp) << "scan " << n;
            if (r.fileStamp <= previous.fileStamp)
                ++stepsBack;
        }
        EXPECT_EQ(r.scan->getScanSize(), 180u);
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6f", r.fileStamp);
        fileStamps.insert(buf);
        previous = r;
        ++n;
    }
    EXPECT_EQ(n, 13631u);        // SOURCES.md
    EXPECT_EQ(stepsBack, 631u);  // SOURCES.md: 631 printed stamps go backwards
    EXPECT_NEAR(previous.scan->aperture, 179 * kDeg, 1e-6);
    EXPECT_GT(reader.adjustedTimestamps(), 631u);
    // Every relation stamp is a fileStamp.
    std::ifstream in(relations);
    std::string t1, t2, rest;
    std::set<std::string> relationStamps;
    while (in >> t1 >> t2 && std::getline(in, rest)) {
        relationStamps.insert(t1);
        relationStamps.insert(t2);
    }
    EXPECT_EQ(relationStamps.size(), 1791u);
    for (const auto& s : relationStamps)
        EXPECT_TRUE(fileStamps.count(s)) << s;
}

TEST(CarmenBenchmark, MitCsailAndFr079Geometry) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(mit, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(fr079, "slam/fr079.clf");
    LaserLogReader reader(mit);
    LaserLogRecord r;
    ASSERT_TRUE(reader.next(r));
    EXPECT_EQ(r.scan->getScanSize(), 361u);
    EXPECT_NEAR(r.scan->aperture, M_PI, 1e-6);
    EXPECT_NEAR(r.scan->sensorPose.yaw(), 0.0, 1e-9);
    EXPECT_EQ(r.fileStamp, 1134864629.895182);
    EXPECT_EQ(r.odometry, mrpt::poses::CPose2D(576.536523, 0.106594, -2.255213));
    EXPECT_FALSE(r.scan->getScanRangeValidity(24)) << "81.91 = no return";
    EXPECT_NEAR(r.scan->getScanRange(0), 1.40, 1e-6);

    LaserLogReader reader2(fr079);
    ASSERT_TRUE(reader2.next(r));
    EXPECT_EQ(r.scan->getScanSize(), 360u);
    EXPECT_NEAR(r.scan->aperture, 179.5 * kDeg, 1e-6);
    EXPECT_NEAR(beamDirection(*r.scan, 0), -M_PI / 2, 1e-6);
    EXPECT_EQ(r.fileStamp, 1211.520329);
}
