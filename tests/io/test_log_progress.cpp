// LaserLogReader::fractionRead() advances with the scans parsed, smoothly, whatever the
// reader's buffering and the file's compression: in a log of equal-sized scans the fraction
// after scan i is i/N within a scan or two (it used to count what zlib and a 1 MiB line buffer
// had pulled, jumping by quarters of a log and sitting at 100 % for its last part).
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/RawlogWriter.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "TestSupport.h"

using namespace toposlam::io;

namespace {

constexpr std::size_t kScans = 1200;

// FLASER lines of equal length (361 readings printed with the same number of digits).
std::string carmenLog() {
    std::ostringstream s;
    s << "PARAM robot_front_laser_max 50.0 nohost 0\n";
    for (std::size_t i = 0; i < kScans; ++i) {
        char stamp[32], x[32];
        std::snprintf(stamp, sizeof stamp, "%.6f", 1000.0 + 0.1 * static_cast<double>(i));
        std::snprintf(x, sizeof x, "%.4f", 1.0 + 0.001 * static_cast<double>(i));
        s << "FLASER 361";
        for (int b = 0; b < 361; ++b)
            s << " 2.50";
        s << ' ' << x << " 0.0000 0.0000 " << x << " 0.0000 0.0000 " << stamp << " host " << stamp
          << "\n";
    }
    return s.str();
}

void writeFile(const std::string& path, const std::string& text, bool gzip) {
    if (gzip) {
        gzFile f = gzopen(path.c_str(), "wb6");
        gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
        gzclose(f);
    } else {
        std::ofstream(path, std::ios::binary) << text;
    }
}

void writeRawlog(const std::string& path, RawlogFormat format) {
    RawlogWriter writer(path, format);
    LaserLogRecord r;
    for (std::size_t i = 0; i < kScans; ++i) {
        auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
        scan->sensorLabel = "LASER";
        scan->resizeScan(361);
        for (std::size_t b = 0; b < 361; ++b) {
            scan->setScanRange(b, 2.5f);
            scan->setScanRangeValidity(b, true);
        }
        scan->timestamp = mrpt::Clock::fromDouble(1000.0 + 0.1 * static_cast<double>(i));
        r.scan = scan;
        r.odometry = mrpt::poses::CPose2D(0.01 * static_cast<double>(i), 0, 0);
        r.hasOdometry = true;
        writer.write(r);
    }
    writer.commit();
}

// The fraction after every scan, in order.
void expectSmoothProgress(const std::string& path) {
    LaserLogReader reader(path);
    LaserLogRecord record;
    std::size_t n = 0;
    double previous = 0, worst = 0;
    while (reader.next(record)) {
        ++n;
        const double f = reader.fractionRead();
        EXPECT_GE(f, previous) << path << " scan " << n;
        previous = f;
        worst = std::max(worst, std::abs(f - static_cast<double>(n) / kScans));
    }
    EXPECT_EQ(n, kScans);
    EXPECT_LT(worst, 2.5 / kScans + 0.002) << path << ": fraction off by " << worst;
    EXPECT_NEAR(previous, 1.0, 1e-9) << path;
}

}  // namespace

TEST(LogProgress, CarmenPlainAndGzip) {
    toposlam::test::TempDir dir;
    const std::string text = carmenLog();
    ASSERT_GT(text.size(), 2u << 20) << "larger than the reader's 1 MiB buffer";
    writeFile(dir.file("log.clf"), text, false);
    writeFile(dir.file("log.clf.gz"), text, true);
    expectSmoothProgress(dir.file("log.clf"));
    expectSmoothProgress(dir.file("log.clf.gz"));
}

TEST(LogProgress, RawlogBothFormatsPlainAndGzip) {
    toposlam::test::TempDir dir;
    for (const auto format : {RawlogFormat::Observations, RawlogFormat::SensoryFrames}) {
        for (const std::string ext : {".rawlog", ".rawlog.gz"}) {
            const std::string path = dir.file(std::string(toString(format)) + ext);
            writeRawlog(path, format);
            expectSmoothProgress(path);
        }
    }
}

// The log of the complaint: the bar jumped 27 -> 54 -> 82 % and sat at 100 % for the last
// 350 scans. Now no step between two scans exceeds 0.5 % and 350 scans before the end the
// bar is near 1 - 350/N.
TEST(LogProgress, MitCsailAdvancesWithEveryScan) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(mit, "slam/mit-csail.clf");
    std::vector<double> fractions;
    LaserLogReader reader(mit);
    LaserLogRecord record;
    while (reader.next(record))
        fractions.push_back(reader.fractionRead());
    ASSERT_GT(fractions.size(), 1000u);
    double largestStep = fractions.front();
    for (std::size_t i = 1; i < fractions.size(); ++i)
        largestStep = std::max(largestStep, fractions[i] - fractions[i - 1]);
    EXPECT_LT(largestStep, 0.005);
    const std::size_t n = fractions.size();
    EXPECT_NEAR(fractions[n - 351], 1.0 - 350.0 / static_cast<double>(n), 0.03);
    EXPECT_NEAR(fractions.back(), 1.0, 1e-9);
}
