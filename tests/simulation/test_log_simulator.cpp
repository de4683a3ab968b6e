#include <gtest/gtest.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/LogSimulator.h>
#include <toposlam/simulation/OfficeFloorPlan.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <filesystem>

#include "SimulationTestMaps.h"
#include "TestSupport.h"

using mrpt::poses::CPose2D;
using namespace toposlam;
using namespace toposlam::simulation;

namespace {

/// A walk through the office corridor and into office S2: 40 poses, 0.25 s apart.
io::Trajectory2D corridorWalk() {
    io::Trajectory2D gt;
    for (int i = 0; i < 40; ++i) {
        const double s = 0.2 * i;
        io::TimedPose2D p;
        p.stamp = 1700000000.0 + 0.25 * i;
        p.pose = i < 30 ? mrpt::math::TPose2D(2.0 + s, 6.5, 0.02 * i)
                        : mrpt::math::TPose2D(7.0, 6.5 - 0.2 * (i - 29), -M_PI / 2);
        gt.push_back(p);
    }
    return gt;
}

LogSimulationOptions exactOptions() {
    LogSimulationOptions o = SimulatorConfig::defaultLog();
    o.laser.rangeNoiseStd = 0;
    o.laser.bearingNoiseStd = 0;
    o.odometry = OdometryErrorModel::exact();
    return o;
}

const mrpt::maps::COccupancyGridMap2D& officeGrid() {
    static const auto grid = makeOfficeFloorPlan().rasterise(0.05, 0.5);
    return grid;
}

}  // namespace

TEST(LogSimulator, NoiseFreeLogReproducesTheGroundTruth) {
    const io::Trajectory2D gt = corridorWalk();
    const LogSimulationOptions options = exactOptions();
    LogSimulator sim(officeGrid(), gt, options);
    const GridWorld world(officeGrid());
    io::LaserLogRecord r;
    std::size_t n = 0;
    while (sim.next(r)) {
        ASSERT_LT(n, gt.size());
        EXPECT_EQ(r.index, n);
        EXPECT_DOUBLE_EQ(r.fileStamp, gt[n].stamp);  // 0.25 s steps are exact in 100 ns ticks
        // Odometry starts at (0,0,0): it is the motion since the first pose.
        const CPose2D expected = CPose2D(gt[n].pose) - CPose2D(gt[0].pose);
        EXPECT_NEAR(r.odometry.x(), expected.x(), 1e-9);
        EXPECT_NEAR(r.odometry.y(), expected.y(), 1e-9);
        EXPECT_NEAR(std::remainder(r.odometry.phi() - expected.phi(), 2 * M_PI), 0, 1e-9);
        ASSERT_TRUE(r.scan);
        EXPECT_EQ(r.scan->sensorLabel, "LASER");
        EXPECT_EQ(r.scan->getScanSize(), 361u);
        EXPECT_NEAR(r.scan->aperture, 1.5 * M_PI, 1e-6);
        EXPECT_NEAR(r.scan->sensorPose.x(), 0.2, 1e-12);
        EXPECT_DOUBLE_EQ(mrpt::Clock::toDouble(r.scan->timestamp), r.fileStamp);
        // Every beam is what the grid world shows from the laser's pose.
        const auto laserPose = mrpt::poses::CPose3D(CPose2D(gt[n].pose)) + r.scan->sensorPose;
        for (std::size_t b = 0; b < r.scan->getScanSize(); b += 30) {
            const double d = world.castRay({laserPose.x(), laserPose.y()},
                                           laserPose.yaw() + r.scan->getScanAngle(b), 20.0);
            ASSERT_EQ(r.scan->getScanRangeValidity(b), std::isfinite(d)) << "max range 20 m";
            if (std::isfinite(d)) {
                EXPECT_NEAR(r.scan->getScanRange(b), d, 1e-5) << "scan " << n << " beam " << b;
            }
        }
        ++n;
    }
    EXPECT_EQ(n, gt.size());
}

TEST(LogSimulator, PeopleOnlyShortenRangesAndDoAppear) {
    const io::Trajectory2D gt = corridorWalk();
    LogSimulationOptions empty = exactOptions(), crowded = exactOptions();
    crowded.people.count = 15;
    LogSimulator a(officeGrid(), gt, empty), b(officeGrid(), gt, crowded);
    io::LaserLogRecord ra, rb;
    std::size_t occluded = 0;
    while (a.next(ra) && b.next(rb)) {
        for (std::size_t i = 0; i < ra.scan->getScanSize(); ++i) {
            const float without = ra.scan->getScanRange(i), with = rb.scan->getScanRange(i);
            // People keep 0.6 m from the robot's centre, so they are never nearer to the laser
            // than its minimum range: a valid beam stays valid (an out-of-range one may now hit
            // a person).
            ASSERT_TRUE(!ra.scan->getScanRangeValidity(i) || rb.scan->getScanRangeValidity(i));
            ASSERT_LE(with, without + 1e-6f) << "a person cannot lengthen a beam";
            occluded += with < without - 0.1f ? 1 : 0;
        }
    }
    EXPECT_GT(occluded, 0u) << "15 people in the office never crossed the laser's view";
}

TEST(LogSimulator, AStalledOdometryRepeatsItsReadingThenCatchesUp) {
    // The same walk with a noisy odometry, without and with stalls: stalls draw from their own
    // generator, so every reading is either the stall-free log's (the odometry caught up) or
    // the one before it (frozen), for at most stall_max_scans scans in a row; the scans are
    // the same.
    const io::Trajectory2D gt = corridorWalk();
    LogSimulationOptions steady = SimulatorConfig::defaultLog(), stalling = steady;
    stalling.odometry.stallProbability = 0.3;
    stalling.odometry.stallMaxScans = 2;
    LogSimulator a(officeGrid(), gt, steady), b(officeGrid(), gt, stalling);
    io::LaserLogRecord ra, rb;
    CPose2D previous;
    std::size_t frozen = 0, inARow = 0, longest = 0;
    while (a.next(ra) && b.next(rb)) {
        const bool repeated = ra.index > 0 && rb.odometry == previous;
        if (repeated && !(rb.odometry == ra.odometry)) {
            ++frozen;
            longest = std::max(longest, ++inARow);
        } else {
            ASSERT_EQ(rb.odometry, ra.odometry) << "scan " << ra.index << ": caught up";
            inARow = 0;
        }
        previous = rb.odometry;
        ASSERT_EQ(ra.scan->getScanSize(), rb.scan->getScanSize());
        for (std::size_t i = 0; i < ra.scan->getScanSize(); ++i)
            ASSERT_EQ(ra.scan->getScanRange(i), rb.scan->getScanRange(i));
    }
    EXPECT_GE(frozen, 3u) << "40 scans at 30 %: stalls must have happened";
    EXPECT_LE(longest, 2u);
}

TEST(LogSimulator, AStallOfTheDistanceAloneFreezesThePositionNotTheHeading) {
    // stall_heading_reads: the wheels' count stops while the heading still reads (mit-csail).
    // Every reading's heading is the stall-free log's; its position is that log's or, frozen,
    // the one before.
    const io::Trajectory2D gt = corridorWalk();
    LogSimulationOptions steady = SimulatorConfig::defaultLog(), stalling = steady;
    stalling.odometry.stallProbability = 0.3;
    stalling.odometry.stallMaxScans = 2;
    stalling.odometry.stallHeadingReads = true;
    LogSimulator a(officeGrid(), gt, steady), b(officeGrid(), gt, stalling);
    io::LaserLogRecord ra, rb;
    CPose2D previous;
    std::size_t frozen = 0;
    while (a.next(ra) && b.next(rb)) {
        ASSERT_EQ(rb.odometry.phi(), ra.odometry.phi()) << "scan " << ra.index;
        const bool samePosition =
            rb.odometry.x() == ra.odometry.x() && rb.odometry.y() == ra.odometry.y();
        if (!samePosition) {
            ASSERT_GT(ra.index, 0u);
            ASSERT_EQ(rb.odometry.x(), previous.x()) << "scan " << ra.index;
            ASSERT_EQ(rb.odometry.y(), previous.y()) << "scan " << ra.index;
            ++frozen;
        }
        previous = rb.odometry;
    }
    EXPECT_GE(frozen, 3u) << "40 scans at 30 %: stalls must have happened";
}

TEST(LogSimulator, RawlogRoundTripsThroughTheLogReaderInBothFormats) {
    const io::Trajectory2D gt = corridorWalk();
    const LogSimulationOptions options = SimulatorConfig::defaultLog();  // with noise
    for (io::RawlogFormat format :
         {io::RawlogFormat::Observations, io::RawlogFormat::SensoryFrames}) {
        toposlam::test::TempDir dir;
        const std::string rawlog = dir.file("sim.rawlog"), gtFile = dir.file("sim_gt.txt");
        EXPECT_EQ(simulateLogToFiles(officeGrid(), gt, options, rawlog, format, gtFile), gt.size());

        // What the simulator produced, record by record, against what the reader reads back.
        LogSimulator sim(officeGrid(), gt, options);
        const auto records = io::LaserLogReader::readAll(rawlog);
        const io::Trajectory2D savedGt = io::loadTrajectory(gtFile);
        ASSERT_EQ(records.size(), gt.size());
        ASSERT_EQ(savedGt.size(), gt.size());
        io::LaserLogRecord expected;
        for (std::size_t i = 0; i < records.size(); ++i) {
            ASSERT_TRUE(sim.next(expected));
            const io::LaserLogRecord& r = records[i];
            EXPECT_EQ(r.fileStamp, savedGt[i].stamp) << "scan and ground truth stamps match";
            EXPECT_EQ(savedGt[i].pose.x, gt[i].pose.x);
            EXPECT_EQ(savedGt[i].pose.phi, gt[i].pose.phi);
            EXPECT_TRUE(r.hasOdometry);
            // Odometry starts at 0, so the sensory-frame format (increments only) agrees too.
            EXPECT_NEAR(r.odometry.x(), expected.odometry.x(), 1e-6);
            EXPECT_NEAR(r.odometry.y(), expected.odometry.y(), 1e-6);
            EXPECT_NEAR(r.odometry.phi(), expected.odometry.phi(), 1e-6);
            ASSERT_EQ(r.scan->getScanSize(), expected.scan->getScanSize());
            EXPECT_EQ(r.scan->sensorLabel, "LASER");
            for (std::size_t b = 0; b < r.scan->getScanSize(); ++b) {
                ASSERT_EQ(r.scan->getScanRange(b), expected.scan->getScanRange(b));
                ASSERT_EQ(r.scan->getScanRangeValidity(b), expected.scan->getScanRangeValidity(b));
            }
        }
    }
}

TEST(LogSimulator, BadTrajectoriesAreRejectedAndLeaveNoFiles) {
    io::Trajectory2D gt = corridorWalk();
    gt[5].stamp = gt[4].stamp;  // a repeated stamp
    toposlam::test::TempDir dir;
    const std::string rawlog = dir.file("bad.rawlog"), gtFile = dir.file("bad_gt.txt");
    EXPECT_THROW(simulateLogToFiles(officeGrid(), gt, exactOptions(), rawlog,
                                    io::RawlogFormat::Observations, gtFile),
                 std::invalid_argument);
    EXPECT_THROW(LogSimulator(officeGrid(), {}, exactOptions()), std::invalid_argument);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "no partial output";
}
