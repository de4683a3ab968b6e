// RawlogWriter -> LaserLogReader round trips in both MRPT formats, plain and gzip, and the
// reader on MRPT's own sample rawlogs.
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/RawlogWriter.h>
#include <toposlam/io/Trajectory.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "LogReadError.h"
#include "TestSupport.h"

namespace fs = std::filesystem;
using namespace toposlam::io;

namespace {

// A robot driving a curve with a 181-beam scanner; every 7th beam invalid.
std::vector<LaserLogRecord> syntheticRecords(std::size_t n) {
    mrpt::random::CRandomGenerator rng(42);
    std::vector<LaserLogRecord> records(n);
    for (std::size_t i = 0; i < n; ++i) {
        LaserLogRecord& r = records[i];
        r.index = i;
        r.fileStamp = 1.6e9 + 0.1 * static_cast<double>(i) + 0.0123;
        r.odometry = mrpt::poses::CPose2D(100 + 0.05 * i, -3 + 0.01 * i * i / 10.0, 0.02 * i - 3);
        r.hasOdometry = true;
        auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
        scan->sensorLabel = "LASER";
        scan->aperture = static_cast<float>(M_PI);
        scan->maxRange = 30.0f;
        scan->sensorPose = mrpt::poses::CPose3D(0.2, 0.01, 0.3, -0.01, 0, 0);
        scan->timestamp = mrpt::Clock::fromDouble(r.fileStamp);
        scan->resizeScan(181);
        for (std::size_t b = 0; b < 181; ++b) {
            scan->setScanRange(b, static_cast<float>(rng.drawUniform(0.1, 29.9)));
            scan->setScanRangeValidity(b, b % 7 != 0);
        }
        r.scan = scan;
    }
    return records;
}

std::vector<LaserLogRecord> writeAndRead(const std::vector<LaserLogRecord>& records,
                                         const std::string& path, RawlogFormat format) {
    RawlogWriter writer(path, format);
    for (const auto& r : records)
        writer.write(r);
    EXPECT_EQ(writer.objectCount(), 2 * records.size());
    writer.commit();
    LaserLogReader reader(path);
    EXPECT_EQ(reader.format(), format == RawlogFormat::SensoryFrames
                                   ? LaserLogFormat::RawlogSensoryFrames
                                   : LaserLogFormat::RawlogObservations);
    std::vector<LaserLogRecord> back;
    LaserLogRecord r;
    while (reader.next(r))
        back.push_back(r);
    EXPECT_EQ(reader.adjustedTimestamps(), 0u);
    return back;
}

void expectSameScans(const std::vector<LaserLogRecord>& a, const std::vector<LaserLogRecord>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(b[i].index, i);
        EXPECT_EQ(b[i].scan->getScanSize(), a[i].scan->getScanSize());
        for (std::size_t k = 0; k < a[i].scan->getScanSize(); ++k) {
            ASSERT_EQ(b[i].scan->getScanRange(k), a[i].scan->getScanRange(k)) << i << " " << k;
            ASSERT_EQ(b[i].scan->getScanRangeValidity(k), a[i].scan->getScanRangeValidity(k));
        }
        EXPECT_EQ(b[i].scan->timestamp, a[i].scan->timestamp);
        EXPECT_NEAR(b[i].fileStamp, a[i].fileStamp, 1e-6);  // 100 ns clock ticks
        EXPECT_EQ(b[i].scan->aperture, a[i].scan->aperture);
        EXPECT_EQ(b[i].scan->maxRange, a[i].scan->maxRange);
        EXPECT_EQ(b[i].scan->sensorLabel, a[i].scan->sensorLabel);
        EXPECT_EQ(b[i].scan->sensorPose, a[i].scan->sensorPose);
    }
}

// Number of top-level objects MRPT itself reads from the file.
std::size_t mrptObjectCount(const std::string& path) {
    mrpt::obs::CRawlog rawlog;
    EXPECT_TRUE(rawlog.loadFromRawLogFile(path));
    return rawlog.size();
}

}  // namespace

TEST(RawlogRoundTrip, ObservationsFormatKeepsEverything) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(50);
    for (const char* name : {"obs.rawlog", "obs.rawlog.gz"}) {
        const auto back = writeAndRead(records, dir.file(name), RawlogFormat::Observations);
        expectSameScans(records, back);
        for (std::size_t i = 0; i < back.size(); ++i) {
            ASSERT_TRUE(back[i].hasOdometry);
            EXPECT_EQ(back[i].odometry, records[i].odometry) << "same stamp: no interpolation";
        }
        EXPECT_EQ(mrptObjectCount(dir.file(name)), 100u);
    }
}

TEST(RawlogRoundTrip, OneLaserKeepsTheFirstScansLaser) {
    // Two lasers, the second one's scan first in each pair: that one is kept.
    toposlam::test::TempDir dir;
    auto records = syntheticRecords(6);
    for (std::size_t i = 0; i < records.size(); ++i)
        records[i].scan->sensorLabel = i % 2 == 0 ? "LASER_REAR" : "LASER_FRONT";
    writeAndRead(records, dir.file("two.rawlog"), RawlogFormat::Observations);
    LaserLogOptions one;
    one.oneLaser = true;
    LaserLogReader reader(dir.file("two.rawlog"), one);
    EXPECT_EQ(reader.laserLabel(), "") << "a rawlog says which only with its first scan";
    LaserLogRecord r;
    std::size_t kept = 0;
    while (reader.next(r)) {
        EXPECT_EQ(r.scan->sensorLabel, "LASER_REAR");
        EXPECT_EQ(r.fileStamp, records[2 * kept].fileStamp);
        ++kept;
    }
    EXPECT_EQ(kept, 3u);
    EXPECT_EQ(reader.laserLabel(), "LASER_REAR");
    EXPECT_EQ(reader.otherLaserScans(), (std::map<std::string, std::size_t>{{"LASER_FRONT", 3}}));
}

TEST(RawlogRoundTrip, SensoryFramesFormatKeepsRelativeOdometry) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(50);
    for (const char* name : {"sf.rawlog", "sf.rawlog.gz"}) {
        const auto back = writeAndRead(records, dir.file(name), RawlogFormat::SensoryFrames);
        expectSameScans(records, back);
        for (std::size_t i = 0; i < back.size(); ++i) {
            ASSERT_TRUE(back[i].hasOdometry);
            // Increments only: odometry relative to the first record. 1e-9: 50 compositions
            // of doubles.
            const mrpt::poses::CPose2D expected = records[i].odometry - records[0].odometry;
            EXPECT_NEAR(back[i].odometry.x(), expected.x(), 1e-9) << i;
            EXPECT_NEAR(back[i].odometry.y(), expected.y(), 1e-9) << i;
            EXPECT_NEAR(back[i].odometry.phi(), expected.phi(), 1e-9) << i;
        }
        EXPECT_EQ(mrptObjectCount(dir.file(name)), 100u);
    }
}

TEST(RawlogRoundTrip, GzipByExtension) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(3);
    {
        RawlogWriter w(dir.file("a.rawlog.gz"), RawlogFormat::Observations);
        for (const auto& r : records)
            w.write(r);
        w.commit();
    }
    std::ifstream in(dir.file("a.rawlog.gz"), std::ios::binary);
    EXPECT_EQ(in.get(), 0x1f);
    EXPECT_EQ(in.get(), 0x8b);
}

TEST(RawlogRoundTrip, WriterWithoutCommitLeavesNoFile) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(3);
    {
        RawlogWriter w(dir.file("a.rawlog"), RawlogFormat::SensoryFrames);
        w.write(records[0]);
    }
    EXPECT_TRUE(fs::is_empty(dir.path()));
    EXPECT_THROW(RawlogWriter(dir.file("no/such/dir/a.rawlog"), RawlogFormat::Observations),
                 std::runtime_error);
}

TEST(RawlogRoundTrip, ObservationsOdometryIsInterpolatedAtScanTime) {
    toposlam::test::TempDir dir;
    const std::string path = dir.file("interp.rawlog");
    const auto records = syntheticRecords(2);
    {
        // odometry at t=10 and t=11, a scan at t=10.25, another after the last sample.
        mrpt::io::CFileGZOutputStream out(path);
        auto archive = mrpt::serialization::archiveFrom(out);
        mrpt::obs::CObservationOdometry o;
        o.timestamp = mrpt::Clock::fromDouble(10.0);
        o.odometry = mrpt::poses::CPose2D(1, 2, 0.5);
        archive << o;
        auto scan = records[0].scan;
        scan->timestamp = mrpt::Clock::fromDouble(10.25);
        archive << *scan;
        o.timestamp = mrpt::Clock::fromDouble(11.0);
        o.odometry = mrpt::poses::CPose2D(1, 2, 0.5) + mrpt::poses::CPose2D(0.4, 0.2, 0.1);
        archive << o;
        scan->timestamp = mrpt::Clock::fromDouble(12.0);
        archive << *scan;
    }
    const auto back = LaserLogReader::readAll(path);
    ASSERT_EQ(back.size(), 2u);
    const mrpt::poses::CPose2D expected =
        mrpt::poses::CPose2D(1, 2, 0.5) + mrpt::poses::CPose2D(0.1, 0.05, 0.025);
    EXPECT_NEAR(back[0].odometry.x(), expected.x(), 1e-6);  // 1e-6: clock ticks of 100 ns
    EXPECT_NEAR(back[0].odometry.y(), expected.y(), 1e-6);
    EXPECT_NEAR(back[0].odometry.phi(), expected.phi(), 1e-6);
    // After the last sample, that sample is held.
    const mrpt::poses::CPose2D last =
        mrpt::poses::CPose2D(1, 2, 0.5) + mrpt::poses::CPose2D(0.4, 0.2, 0.1);
    EXPECT_NEAR(back[1].odometry.x(), last.x(), 1e-12);
    EXPECT_NEAR(back[1].odometry.phi(), last.phi(), 1e-12);
}

namespace {

using toposlam::test::logReadError;

using toposlam::test::readFile;

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST(RawlogBadInput, MissingEmptyGarbage) {
    toposlam::test::TempDir dir;
    EXPECT_NE(logReadError(dir.file("none.rawlog")).find("none.rawlog: file not found"),
              std::string::npos);
    writeBytes(dir.file("empty.rawlog"), "");
    EXPECT_NE(logReadError(dir.file("empty.rawlog")).find("empty.rawlog: file is empty"),
              std::string::npos);
    writeBytes(dir.file("garbage.rawlog"), std::string("\x01\x02\x03\xff\xfe garbage", 13));
    EXPECT_NE(
        logReadError(dir.file("garbage.rawlog")).find("neither a CARMEN log nor an MRPT rawlog"),
        std::string::npos);
    // A PNG: MRPT reads its first bytes as a class name, NUL and control characters included;
    // shown escaped (a NUL cut the message short).
    writeBytes(dir.file("image.rawlog"),
               std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\0\x01\0\0\0\x01", 24));
    const std::string png = logReadError(dir.file("image.rawlog"));
    EXPECT_NE(png.find("image.rawlog: neither a CARMEN log nor an MRPT rawlog"), std::string::npos)
        << png;
    EXPECT_EQ(png.find('\0'), std::string::npos) << png;
    EXPECT_EQ(png.find('\r'), std::string::npos) << png;
}

TEST(RawlogBadInput, TruncatedStreamIsAnErrorNotAnEnd) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(10);
    for (const char* name : {"t.rawlog", "t.rawlog.gz"}) {
        RawlogWriter w(dir.file(name), RawlogFormat::Observations);
        for (const auto& r : records)
            w.write(r);
        w.commit();
        const std::string bytes = readFile(dir.file(name));
        const std::string cut = std::string("cut-") + name;
        writeBytes(dir.file(cut), bytes.substr(0, bytes.size() * 2 / 3));
        const std::string error = logReadError(dir.file(cut));
        EXPECT_NE(error.find(cut + ": object #"), std::string::npos) << error;
        EXPECT_NE(error.find("truncated or corrupt"), std::string::npos) << error;
    }
}

// A distance or an odometry pose that is NaN or infinite is corrupt data, as in a CARMEN log:
// MRPT stores it without complaint (and its grid asserts on it much later), the reader names
// the object.
TEST(RawlogBadInput, NonFiniteReadingsAndOdometryAreErrors) {
    toposlam::test::TempDir dir;
    const auto corrupt = [&](const std::string& name, auto change, std::size_t record) {
        auto records = syntheticRecords(5);
        change(records[record]);
        RawlogWriter w(dir.file(name), RawlogFormat::Observations);
        for (const auto& r : records)
            w.write(r);
        w.commit();
        return logReadError(dir.file(name));
    };
    const std::string nanRange = corrupt(
        "nan.rawlog", [](LaserLogRecord& r) { r.scan->setScanRange(3, NAN); }, 2);
    // Objects: odometry, scan, odometry, scan, ...: the third scan is object #5.
    EXPECT_NE(nanRange.find("nan.rawlog: object #5, a CObservation2DRangeScan: reading 3 is nan"),
              std::string::npos)
        << nanRange;
    const std::string infRange = corrupt(
        "inf.rawlog", [](LaserLogRecord& r) { r.scan->setScanRange(1, -INFINITY); }, 0);
    EXPECT_NE(infRange.find("reading 1 is -inf"), std::string::npos) << infRange;
    const std::string nanOdometry = corrupt(
        "odo.rawlog", [](LaserLogRecord& r) { r.odometry.x(NAN); }, 1);
    EXPECT_NE(nanOdometry.find("odo.rawlog: object #2, a CObservationOdometry: the odometry pose "
                               "is not finite"),
              std::string::npos)
        << nanOdometry;
    // An invalid reading may hold anything.
    const auto records = syntheticRecords(3);
    records[1].scan->setScanRange(7, NAN);  // beam 7 is invalid
    RawlogWriter w(dir.file("ok.rawlog"), RawlogFormat::Observations);
    for (const auto& r : records)
        w.write(r);
    w.commit();
    EXPECT_EQ(logReadError(dir.file("ok.rawlog")), "");
}

// Objects of classes the reader's check does not know (here a CObservationComment) are read
// after a dry run in a child process: a sound one is skipped, one whose string length claims
// 2 GB is an error, and the reader itself never allocates that.
TEST(RawlogBadInput, UncheckedClassesAreSkippedOrBoundedInMemory) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(2);
    const std::string marker = "TopoSLAM comment marker";
    {
        mrpt::io::CFileGZOutputStream file(dir.file("comment.rawlog"));
        auto out = mrpt::serialization::archiveFrom(file);
        mrpt::obs::CObservationComment comment;
        comment.text = marker;
        out << *records[0].scan << comment << *records[1].scan;
    }
    EXPECT_EQ(LaserLogReader::readAll(dir.file("comment.rawlog")).size(), 2u);

    // The same file, plain, with the comment's length field (before its text) set to 2^31 - 1.
    std::string bytes;
    {
        mrpt::io::CFileGZInputStream in(dir.file("comment.rawlog"));
        char buf[4096];
        for (std::size_t n; (n = in.Read(buf, sizeof buf)) > 0;)
            bytes.append(buf, n);
    }
    const auto at = bytes.find(marker);
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at - 4, 4, std::string("\xff\xff\xff\x7f", 4));
    writeBytes(dir.file("huge.rawlog"), bytes);
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    const std::string error = logReadError(dir.file("huge.rawlog"));
    getrusage(RUSAGE_SELF, &after);
    EXPECT_NE(error.find("huge.rawlog: object #1 (after a mrpt::obs::CObservation2DRangeScan), a "
                         "mrpt::obs::CObservationComment: "),
              std::string::npos)
        << error;
    // "needs more than 1024 MiB" (bad_alloc under the child's memory limit), or, under
    // AddressSanitizer, whose allocator ignores RLIMIT_AS and aborts instead, "crashed or
    // exceeded 1024 MiB".
    EXPECT_NE(error.find("1024 MiB"), std::string::npos) << error;
    EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 200 * 1024) << "KiB more at peak";
}

TEST(RawlogBadInput, UnregisteredClassIsAnError) {
    toposlam::test::TempDir dir;
    const auto records = syntheticRecords(3);
    {
        RawlogWriter w(dir.file("ok.rawlog"), RawlogFormat::Observations);
        for (const auto& r : records)
            w.write(r);
        w.commit();
    }
    // Append an object of a class nobody registered: header byte (0x80 | name length), name,
    // version, some payload. MRPT's own readers stop here silently.
    const std::string name = "plugin::CObservationSomething";
    std::string object(1, static_cast<char>(0x80 | name.size()));
    object += name;
    object += std::string("\x00payload", 8);
    writeBytes(dir.file("unreg.rawlog"), readFile(dir.file("ok.rawlog")) + object);
    const std::string error = logReadError(dir.file("unreg.rawlog"));
    EXPECT_NE(error.find("unreg.rawlog: object #6 (after a mrpt::obs::CObservation2DRangeScan): "
                         "class 'plugin::CObservationSomething' is not registered"),
              std::string::npos)
        << error;
    // The records before it are delivered; the error comes where the stream breaks.
    LaserLogReader reader(dir.file("unreg.rawlog"));
    LaserLogRecord r;
    std::size_t n = 0;
    EXPECT_THROW(while (reader.next(r))++ n, InputError);
    EXPECT_EQ(n, 3u) << "the scans before the unknown object are delivered";
}

TEST(RawlogSamples, BothFormatsOfTheSameRecordingAgree) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(sf, "rawlog/driving_in_office.rawlog");
    TOPOSLAM_SHARED_DATA_OR_SKIP(obs, "rawlog/driving_in_office_obs.rawlog");
    const auto a = LaserLogReader::readAll(sf);
    const auto b = LaserLogReader::readAll(obs);
    // SOURCES.md: 1159 scans in the observations file, 1137-1159 in the SF one.
    EXPECT_EQ(b.size(), 1159u);
    EXPECT_GE(a.size(), 1137u);
    for (const auto* log : {&a, &b}) {
        for (std::size_t i = 0; i < log->size(); ++i) {
            const auto& r = (*log)[i];
            ASSERT_EQ(r.scan->getScanSize(), 626u);
            EXPECT_NEAR(r.scan->aperture, 220.0 * M_PI / 180, 1e-3);
            EXPECT_EQ(r.scan->sensorLabel, "FLASER");
            if (i > 0) {
                EXPECT_GT(r.scan->timestamp, (*log)[i - 1].scan->timestamp);
            }
        }
    }
    // The SF file's actions were made from the same odometry samples (10 Hz), so its
    // odometry at a scan is the last sample before the scan, while the observations file's is
    // interpolated at the scan's time: they differ by at most the motion in one odometry
    // period, bounded by the largest motion between consecutive scans (also ~10 Hz).
    double maxStep = 0, maxTurn = 0;
    for (std::size_t i = 1; i < b.size(); ++i) {
        const auto d = b[i].odometry - b[i - 1].odometry;
        maxStep = std::max(maxStep, std::hypot(d.x(), d.y()));
        maxTurn = std::max(maxTurn, std::abs(d.phi()));
    }
    std::size_t compared = 0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        while (j + 1 < b.size() && b[j].fileStamp < a[i].fileStamp - 1e-6)
            ++j;
        if (std::abs(b[j].fileStamp - a[i].fileStamp) > 1e-6)
            continue;
        const auto d = a[i].odometry - b[j].odometry;
        EXPECT_LE(std::hypot(d.x(), d.y()), maxStep + 1e-6) << i;
        EXPECT_LE(std::abs(d.phi()), maxTurn + 1e-6) << i;
        ++compared;
    }
    EXPECT_GT(compared, 1000u);
}

TEST(RawlogSamples, MrptSampleLogs) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(sena,
                                 "rawlog/2006-01ENE-21-SENA_Telecom_Faculty_one_loop_only.rawlog");
    const auto records = LaserLogReader::readAll(sena);
    EXPECT_GE(records.size(), 224u);  // SOURCES.md: 224-225 scans
    EXPECT_LE(records.size(), 225u);
    EXPECT_EQ(records.front().scan->getScanSize(), 361u);
    EXPECT_NEAR(records.front().scan->sensorPose.x(), 0.78, 1e-6);
}

TEST(RawlogSamples, SimulatedLogStartsWithoutOdometry) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(simul, "rawlog/simul.rawlog");
    TOPOSLAM_SHARED_DATA_OR_SKIP(gt, "rawlog/simul.rawlog.GT.txt");
    const auto records = LaserLogReader::readAll(simul);
    // SOURCES.md: 1732 odometry actions + 1733 scans; the file starts with a sensory frame,
    // so the first scan has no odometry.
    ASSERT_EQ(records.size(), 1733u);
    EXPECT_FALSE(records.front().hasOdometry);
    EXPECT_TRUE(std::all_of(records.begin() + 1, records.end(),
                            [](const LaserLogRecord& r) { return r.hasOdometry; }));
    EXPECT_EQ(records.front().scan->sensorLabel, "LASER_SIM");
    // Its ground truth is a 'timestamp x y phi' file, which Trajectory.h reads.
    EXPECT_EQ(toposlam::io::loadTrajectory(gt).size(), 1734u);
}

namespace {

// Robot-frame point of reading i, from the scan's full 3D sensor pose (as MRPT projects it).
mrpt::math::TPoint3D pointIn3D(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
    const double a = scan.getScanAngle(i), r = scan.getScanRange(i);
    return scan.sensorPose.composePoint(mrpt::math::TPoint3D(r * std::cos(a), r * std::sin(a), 0));
}

// The same point as 2D code reads it: the sensor pose as CPose2D(x, y, yaw).
mrpt::math::TPoint2D pointIn2D(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i) {
    const double a = scan.getScanAngle(i), r = scan.getScanRange(i);
    const mrpt::poses::CPose2D sensor(scan.sensorPose);
    const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());
    return {sensor.x() + r * (c * std::cos(a) - s * std::sin(a)),
            sensor.y() + r * (s * std::cos(a) + c * std::sin(a))};
}

}  // namespace

TEST(RawlogUpsideDownLaser, IsReadAsAnUprightLaserWithEveryPointInPlace) {
    toposlam::test::TempDir dir;
    const std::string path = dir.file("mounts.rawlog");
    const auto records = syntheticRecords(1);
    // yaw, pitch, roll of the mount: rolled over, pitched over (facing backwards), both ways
    // of a 3 deg tolerance, upright, and tilted (a 2D laser looking at the floor: left alone).
    const double kDeg = M_PI / 180;
    const std::vector<std::array<double, 3>> mounts = {{0.3, 0, M_PI},
                                                       {0.3, M_PI, 0},
                                                       {-2.0, 2 * kDeg, M_PI - 2 * kDeg},
                                                       {0.3, 0, 0},
                                                       {0.3, 0, 30 * kDeg}};
    std::vector<mrpt::obs::CObservation2DRangeScan> written;
    {
        mrpt::io::CFileGZOutputStream out(path);
        auto archive = mrpt::serialization::archiveFrom(out);
        for (std::size_t k = 0; k < mounts.size(); ++k) {
            auto scan = *records[0].scan;
            scan.rightToLeft = k % 2 == 0;  // both sweep directions
            scan.sensorPose =
                mrpt::poses::CPose3D(0.2, -0.1, 0.4, mounts[k][0], mounts[k][1], mounts[k][2]);
            scan.timestamp = mrpt::Clock::fromDouble(10.0 + k);
            archive << scan;
            written.push_back(scan);
        }
    }
    LaserLogReader reader(path);
    LaserLogRecord r;
    for (std::size_t k = 0; k < mounts.size(); ++k) {
        ASSERT_TRUE(reader.next(r));
        const auto& original = written[k];
        const bool upsideDown = k < 3;
        EXPECT_EQ(r.scan->rightToLeft, upsideDown ? !original.rightToLeft : original.rightToLeft)
            << "mount " << k;
        if (k == 4) {
            EXPECT_NEAR(r.scan->sensorPose.roll(), 30 * kDeg, 1e-12) << "a tilted laser stays";
            continue;
        }
        EXPECT_NEAR(r.scan->sensorPose.pitch(), 0.0, 1e-12);
        EXPECT_NEAR(r.scan->sensorPose.roll(), 0.0, 1e-12);
        for (std::size_t i = 0; i < original.getScanSize(); ++i) {
            // The 2.8 deg tilt of mount 2 shortens a reading's ground projection by up to
            // r (1 - cos 2.8 deg) = 0.0012 r; the others are exact (float ranges).
            const double tolerance = 1e-5 + (k == 2 ? 0.005 * original.getScanRange(i) : 0.0);
            const auto expected = pointIn3D(original, i);
            const auto got = pointIn2D(*r.scan, i);
            ASSERT_NEAR(got.x, expected.x, tolerance) << "mount " << k << ", reading " << i;
            ASSERT_NEAR(got.y, expected.y, tolerance) << "mount " << k << ", reading " << i;
        }
    }
    EXPECT_EQ(reader.upsideDownScans(), 3u);
}
