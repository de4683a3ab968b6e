// CGraphSlamBuilder driven the way MRPT drives its own map builders (actions + sensory
// frames), and the files toposlam-slam writes from it read back with MRPT's own readers.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/mrptslam/CGraphSlamBuilder.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "SimulatedDrive.h"
#include "TestSupport.h"

using mrpt::poses::CPose2D;
using namespace toposlam;

namespace {

/// A room with a cabinet and a pillar, and a path round it that ends where it began.
test::SimulatedDrive roomTour() {
    simulation::PolygonWorld w;
    w.addPolygon({{0, 0}, {10, 0}, {10, 7}, {0, 7}});
    w.addPolygon({{4, 3}, {6, 3}, {6, 4}, {4, 4}});
    w.addPolygon({{0.01, 5}, {0.6, 5}, {0.6, 6.2}, {0.01, 6.2}});
    w.addDisc({{8, 5.5}, 0.2});
    const auto truth =
        test::drivePath({{1.5, 1.5}, {8.5, 1.5}, {8.5, 5.5}, {1.5, 5.5}, {1.5, 1.5}});
    test::OdometryErrors errors;
    errors.distanceScale = 1.03;
    errors.turnScale = 1.03;
    return test::simulateDrive(w, truth, errors, 11);
}

}  // namespace

TEST(CGraphSlamBuilder, DrivenByActionsAndSensoryFramesLikeMrptBuilders) {
    const auto drive = roomTour();
    mrptslam::CGraphSlamBuilder builder;
    builder.loadFromConfigFile(mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    builder.initialize();
    for (std::size_t i = 0; i < drive.scans.size(); ++i) {
        mrpt::obs::CActionCollection actions;
        if (i > 0) {
            mrpt::obs::CActionRobotMovement2D move;
            move.computeFromOdometry(drive.odometry[i] - drive.odometry[i - 1], {});
            actions.insert(move);
        }
        mrpt::obs::CSensoryFrame frame;
        frame.insert(drive.scans[i]);
        builder.processActionObservation(actions, frame);
    }
    builder.finish();

    // The estimate follows the truth far better than the odometry (3 % scale errors).
    mrpt::poses::CPose3D mean;
    builder.getCurrentPoseEstimation()->getMean(mean);
    const CPose2D estimate(mean);
    const CPose2D truthEnd = drive.truth.back() - drive.truth.front();
    const CPose2D odometryEnd = drive.odometry.back() - drive.odometry.front();
    const double error = (estimate - truthEnd).norm(),
                 odometryError = (odometryEnd - truthEnd).norm();
    EXPECT_LT(error, 0.1) << "odometry is off by " << odometryError << " m";
    EXPECT_GT(odometryError, 0.3);

    // The map handed out: one frame per keyframe, with its scan and its features.
    mrpt::maps::CSimpleMap keyframes;
    builder.getCurrentlyBuiltMap(keyframes);
    ASSERT_GT(keyframes.size(), 5u);
    EXPECT_EQ(keyframes.size(), builder.getCurrentlyBuiltMapSize());
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        const auto& frame = *keyframes.getAsPair(i).sf;
        EXPECT_TRUE(frame.getObservationByClass<mrpt::obs::CObservation2DRangeScan>());
        const auto features = frame.getObservationByClass<features::CObservationLaserFeatures>();
        ASSERT_TRUE(features);
        EXPECT_FALSE(features->features.segments.empty());
    }
    const auto* metric = builder.getCurrentlyBuiltMetricMap();
    ASSERT_TRUE(metric);
    const auto grid = metric->mapByClass<mrpt::maps::COccupancyGridMap2D>();
    ASSERT_TRUE(grid);
    EXPECT_GT(grid->getSizeX() * grid->getSizeY(), 0u);
}

// MRPT's tools hand the builder scans as logged: an upside-down laser's (a roll of 180 deg,
// readings sweeping the other way) is mapped as the upright laser it mirrors.
TEST(CGraphSlamBuilder, AnUpsideDownLaserIsMappedAsTheUprightOne) {
    const auto drive = roomTour();
    const auto run = [&](bool upsideDown) {
        mrptslam::CGraphSlamBuilder builder;
        builder.loadFromConfigFile(mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
        builder.initialize();
        for (std::size_t i = 0; i < drive.scans.size(); ++i) {
            auto odometry = mrpt::obs::CObservationOdometry::Create();
            odometry->odometry = drive.odometry[i];
            builder.processObservation(odometry);
            auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>(*drive.scans[i]);
            if (upsideDown) {
                scan->rightToLeft = !scan->rightToLeft;
                scan->sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, 0, M_PI);
            }
            builder.processObservation(scan);
        }
        builder.finish();
        mrpt::poses::CPose3D mean;
        builder.getCurrentPoseEstimation()->getMean(mean);
        return CPose2D(mean);
    };
    const CPose2D upright = run(false), upsideDown = run(true);
    const CPose2D truthEnd = drive.truth.back() - drive.truth.front();
    EXPECT_LT((upright - truthEnd).norm(), 0.1);
    EXPECT_NEAR(upsideDown.x(), upright.x(), 1e-6);
    EXPECT_NEAR(upsideDown.y(), upright.y(), 1e-6);
    EXPECT_NEAR(upsideDown.phi(), upright.phi(), 1e-6);
}

TEST(CGraphSlamBuilder, MapsTheFirstLaserAndSkipsOthersKeepingTheirOdometry) {
    // Observations one at a time, as an observations-format rawlog gives them: odometry, then
    // (after the first step) a second laser's scan (all readings 1 m: nothing like the room),
    // then the first laser's. The second laser is left out and counted, and the odometry read
    // before it still moves the robot: the trajectory is bit for bit that of the first laser
    // alone.
    const auto drive = roomTour();
    const auto run = [&](bool withOther) {
        auto builder = std::make_unique<mrptslam::CGraphSlamBuilder>();
        builder->loadFromConfigFile(
            mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
        builder->initialize();
        for (std::size_t i = 0; i < drive.scans.size(); ++i) {
            auto odometry = mrpt::obs::CObservationOdometry::Create();
            odometry->odometry = drive.odometry[i];
            odometry->timestamp = drive.scans[i]->timestamp;
            builder->processObservation(odometry);
            if (withOther && i > 0) {
                auto other = mrpt::obs::CObservation2DRangeScan::Create(*drive.scans[i]);
                other->sensorLabel = "OTHER_LASER";
                for (std::size_t b = 0; b < other->getScanSize(); ++b)
                    other->setScanRange(b, 1.0f);
                builder->processObservation(other);
            }
            builder->processObservation(drive.scans[i]);
        }
        builder->finish();
        return builder;
    };
    const auto alone = run(false), both = run(true);
    ASSERT_TRUE(both->laserLabel());
    EXPECT_EQ(*both->laserLabel(), drive.scans.front()->sensorLabel);
    EXPECT_EQ(both->otherLaserScans(),
              (std::map<std::string, std::size_t>{{"OTHER_LASER", drive.scans.size() - 1}}));
    EXPECT_TRUE(alone->otherLaserScans().empty());
    ASSERT_EQ(both->slam().statistics().scans, drive.scans.size());
    const auto a = alone->slam().scanPoses(), b = both->slam().scanPoses();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_EQ(a[i], b[i]) << "scan " << i;
}

TEST(CGraphSlamBuilder, AppOutputsAreReadByMrpt) {
    const test::TempDir dir;
    const auto drive = roomTour();
    test::writeRawlog(drive, dir.file("tour.rawlog"));
    const auto run = test::runApp("toposlam-slam", "'" + test::configIni("toposlam-slam.ini") +
                                                       "' '" + dir.file("tour.rawlog") + "' -o '" +
                                                       dir.file("out") + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto summary = io::loadJsonFile(dir.file("out/summary.json"));
    const std::size_t keyframes = summary.at("keyframes").get<std::size_t>();
    EXPECT_EQ(summary.at("scans").get<std::size_t>(), drive.scans.size());
    EXPECT_FALSE(summary.at("mostly_unregistered").get<bool>());

    // keyframes.graph: MRPT's .graph text format, one node per keyframe.
    mrpt::graphs::CNetworkOfPoses2DInf graph;
    graph.loadFromTextFile(dir.file("out/keyframes.graph"));
    EXPECT_EQ(graph.nodes.size(), keyframes);
    EXPECT_GE(graph.edgeCount(), keyframes - 1);

    // keyframes.simplemap: MRPT's CSimpleMap, scans with their features.
    mrpt::maps::CSimpleMap simplemap;
    mrpt::io::CFileGZInputStream in(dir.file("out/keyframes.simplemap"));
    mrpt::serialization::archiveFrom(in) >> simplemap;
    ASSERT_EQ(simplemap.size(), keyframes);
    EXPECT_TRUE(
        simplemap.getAsPair(0).sf->getObservationByClass<features::CObservationLaserFeatures>());
}

// The summary names the loop rules that are off instead of counting what they could not do,
// and says whether the odometry's distances were calibrated, and how long they read.
TEST(CGraphSlamBuilder, SummarySaysWhichLoopRulesRan) {
    const test::TempDir dir;
    test::writeRawlog(roomTour(), dir.file("tour.rawlog"));
    // The shipped ini has the contested rule and the gate's lever arm on, the other two off.
    const std::string shipped = test::readFile(test::configIni("toposlam-slam.ini"));
    const auto edited = [&](std::vector<std::pair<std::string, std::string>> edits,
                            const std::string& name) {
        std::string ini = shipped;
        for (const auto& [from, to] : edits) {
            const auto at = ini.find(from);
            EXPECT_NE(at, std::string::npos) << from;
            if (at != std::string::npos)
                ini.replace(at, from.size(), to);
        }
        std::ofstream(dir.file(name)) << ini;
        return dir.file(name);
    };
    const std::string rulesOn =
        edited({{"\nglobal_search_every = 0", "\nglobal_search_every = 10"},
                {"\nodometry_calibration = false", "\nodometry_calibration = true"}},
               "rules-on.ini");
    const std::string rulesOff =
        edited({{"\nloop_contested_support = 4", "\nloop_contested_support = 0"},
                {"\nloop_gate_lever_arm = true", "\nloop_gate_lever_arm = false"}},
               "rules-off.ini");
    for (const bool on : {false, true}) {
        const std::string out = dir.file(on ? "on" : "off");
        const auto run =
            test::runApp("toposlam-slam", "'" + (on ? rulesOn : rulesOff) + "' '" +
                                              dir.file("tour.rawlog") + "' -o '" + out + "'");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const std::string text = test::readFile(out + "/summary.txt");
        const auto loops = io::loadJsonFile(out + "/summary.json").at("loops");
        EXPECT_EQ(loops.at("guess_free_search").get<bool>(), on);
        EXPECT_EQ(loops.at("contested_rule").get<bool>(), on);
        EXPECT_EQ(loops.at("lever_arm_gate").get<bool>(), on);
        EXPECT_TRUE(loops.at("lever_arm_accepted").is_number_unsigned());
        const auto odometry = io::loadJsonFile(out + "/summary.json").at("odometry");
        EXPECT_EQ(odometry.at("calibration").get<bool>(), on);
        // The evidence is gathered either way (this tour's odometry reads 3 % long); only the
        // calibration applies it, and the summary suggests it when it is off.
        EXPECT_GT(odometry.at("calibration_distance_m").get<double>(), 10);
        EXPECT_TRUE(odometry.at("scale_estimated").get<bool>());
        const double estimate = odometry.at("estimated_scale").get<double>();
        EXPECT_NEAR(estimate, 0.97, 0.01);
        EXPECT_EQ(odometry.at("distance_scale").get<double>(), on ? estimate : 1.0);
        EXPECT_NE(
            text.find(on ? "odometry: distances scaled by " : "(odometry_calibration off); over "),
            std::string::npos)
            << text;
        EXPECT_EQ(
            text.find("odometry_calibration = true keeps that out of the map") != std::string::npos,
            !on)
            << text;
        // Every along-heading check is listed, the held ones among them.
        const auto registration = io::loadJsonFile(out + "/summary.json").at("registration");
        const auto& checks = registration.at("along_heading_checks");
        ASSERT_TRUE(checks.is_array());
        std::size_t held = 0;
        for (const auto& c : checks)
            held += c.at("held").get<bool>();
        EXPECT_GE(held, registration.at("icp_held_along_heading").get<std::size_t>());
        // The shipped ini places the scans between keyframes with odometry too.
        EXPECT_TRUE(io::loadJsonFile(out + "/summary.json").at("smoothed_scans").get<bool>());
        EXPECT_NE(text.find("placed by registration and odometry together"), std::string::npos)
            << text;
        if (on) {
            EXPECT_NE(text.find(" of them guess-free, "), std::string::npos) << text;
            EXPECT_NE(text.find(" beyond the gate on agreeing evidence, "), std::string::npos)
                << text;
            EXPECT_NE(text.find(" let in by the gate's lever arm)"), std::string::npos) << text;
        } else {
            EXPECT_NE(text.find("(guess-free search off, acceptance beyond the gate off, the "
                                "gate's lever arm off)"),
                      std::string::npos)
                << text;
        }
    }
}
