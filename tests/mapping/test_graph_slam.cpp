// The graph SLAM on simulated drives with exact ground truth: loops are closed, look-alike
// rooms are not confused, odometry jumps are recovered, and bad logs give clear errors.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/evaluation/AbsoluteTrajectoryError.h>
#include <toposlam/evaluation/GroundTruthRelations.h>
#include <toposlam/evaluation/IniWithSettings.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>
#include <toposlam/evaluation/SimulatedSlamLogs.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/MirrorImage.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/mapping/GraphSlam.h>
#include <toposlam/mapping/LogMapper.h>
#include <toposlam/mapping/MappingOutputs.h>
#include <toposlam/mapping/ScanRegistration.h>
#include <toposlam/simulation/FloorPlanGenerator.h>
#include <toposlam/simulation/FloorPlanImages.h>
#include <toposlam/simulation/SimulationJob.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <random>
#include <regex>
#include <stdexcept>
#include <utility>

#include "SimulatedDrive.h"
#include "TestSupport.h"

using mrpt::poses::CPose2D;
using namespace toposlam;

namespace {

/// toposlam-sim's tour of the project's office (share/office) with `config`, written into
/// `dir` (office.rawlog and its ground truth office_gt.txt).
simulation::SimulationJob simulateOfficeTour(const simulation::SimulatorConfig& config,
                                             const std::string& dir) {
    simulation::SimulationJob job;
    job.mapPath = test::shareDir() + "/office/office.gridmap.gz";
    job.rawlogPath = dir + "/office.rawlog";
    job.groundTruthPath = dir + "/office_gt.txt";
    simulation::runSimulation(simulation::planSimulation(config, job), config, job);
    return job;
}

/// The office toured with six people walking about (toposlam-sim --tour --people 6 --seed 2),
/// into `dir`.
simulation::SimulationJob simulateOfficeTourWithPeople(const std::string& dir) {
    simulation::SimulatorConfig config;
    config.log.people.count = 6;
    config.log.seed = 2;
    return simulateOfficeTour(config, dir);
}

/// Generated building `seed` of `style` (B4-gen's gen<seed>, B4-rings' ring<seed>, ...) drawn
/// into `dir` as plan.png and its companions, and toured by toposlam-sim with `simIni` and
/// `moreArgs` into plan.rawlog and plan_gt.txt (the paths returned).
struct GeneratedTour {
    std::string log, groundTruth;
    test::CommandResult sim;
};
/// `plan` (a drawn floor plan: grey furniture stops the laser) toured through every room by
/// toposlam-sim configured by `simIni`, as B3-sim does.
GeneratedTour tourPlan(const test::TempDir& dir, const std::string& plan, const std::string& simIni,
                       const std::string& moreArgs = "") {
    GeneratedTour tour{dir.file("plan.rawlog"), dir.file("plan_gt.txt"), {}};
    tour.sim =
        test::runApp("toposlam-sim", "'" + plan + "' --drawn --tour -q -c '" + simIni + "' -o '" +
                                         tour.log + "' --gt '" + tour.groundTruth + "'" + moreArgs);
    return tour;
}

GeneratedTour tourGeneratedBuilding(const test::TempDir& dir, unsigned seed,
                                    simulation::BuildingStyle style, const std::string& simIni,
                                    const std::string& moreArgs = "") {
    simulation::FloorPlanGeneratorOptions options;
    options.style = style;
    const auto images = simulation::drawFloorPlan(simulation::generateFloorPlan(seed, options));
    simulation::saveFloorPlanImages(images, dir.path(), "plan");
    return tourPlan(dir, dir.file("plan_furnitures.png"), simIni, moreArgs);
}

/// The configuration of B3-sim's robot `robot` (evaluation::simulatedRobots(): its settings over
/// config_ini/sim-office.ini), written into `dir`.
std::string benchRobotIni(const test::TempDir& dir, const std::string& robot) {
    const evaluation::SimulatedRobot* settings = evaluation::findSimulatedRobot(robot);
    if (!settings)
        throw std::runtime_error("no simulated robot named " + robot);
    const std::string simIni = dir.file(robot + ".ini");
    evaluation::writeIniWithSettings(test::configIni("sim-office.ini"), simIni, settings->settings);
    return simIni;
}

/// The toposlam-sim arguments B3-sim gives robot `robot` beyond its configuration (the people
/// robot's --people 15), then --seed `seed`.
std::string benchRobotArguments(const std::string& robot, int seed) {
    std::string arguments;
    for (const std::string& a : evaluation::findSimulatedRobot(robot)->simulatorArguments)
        arguments += " " + a;
    return arguments + " --seed " + std::to_string(seed);
}

/// Generated building `building` of `style` toured, as above, by B3-sim's robot `robot` with
/// `seed`.
GeneratedTour tourByBenchRobot(const test::TempDir& dir, unsigned building,
                               simulation::BuildingStyle style, const std::string& robot,
                               int seed) {
    return tourGeneratedBuilding(dir, building, style, benchRobotIni(dir, robot),
                                 benchRobotArguments(robot, seed));
}

/// Drawn floor plan `plan` toured, as above, by B3-sim's robot `robot` with `seed`.
GeneratedTour tourPlanByBenchRobot(const test::TempDir& dir, const std::string& plan,
                                   const std::string& robot, int seed) {
    return tourPlan(dir, plan, benchRobotIni(dir, robot), benchRobotArguments(robot, seed));
}

/// `tour`'s log with one scan in three kept (a third of its scan rate), written into `dir`.
std::string thirdOfTheScans(const test::TempDir& dir, const GeneratedTour& tour) {
    io::LogConversionOptions third;
    third.alteration.keepEvery = 3;
    third.rawlogPath = dir.file("third.rawlog");
    io::convertLaserLog(tour.log, third);
    return third.rawlogPath;
}

/// `log` mapped with the shipped configuration and one [GraphSlam] setting changed: its
/// position ATE against `truth` (m) and the run's statistics.
struct FlaggedRun {
    double ate = 0;
    mapping::SlamStatistics statistics;
};
/// Maps `log` with the shipped configuration and [GraphSlam] `key` set to `value`, and each
/// of `alsoOff` set to false (another rule that mends the same tour, left out to test this one).
FlaggedRun mapWithSetting(const std::string& log, const io::Trajectory2D& truth,
                          const std::string& key, const std::string& value,
                          std::initializer_list<const char*> alsoOff = {}) {
    mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
    ini.write("GraphSlam", key, value);
    for (const char* other : alsoOff)
        ini.write("GraphSlam", other, "false");
    const mapping::MappingResult result = mapping::mapLog(log, ini);
    FlaggedRun run;
    EXPECT_TRUE(result.statistics);
    if (result.statistics)
        run.statistics = *result.statistics;
    const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
    EXPECT_EQ(ate.matchedPoses, result.trajectory.size());
    run.ate = ate.position.rms;
    return run;
}
/// The same with the flag `key` set to `on`.
FlaggedRun mapWithFlag(const std::string& log, const io::Trajectory2D& truth,
                       const std::string& key, bool on,
                       std::initializer_list<const char*> alsoOff = {}) {
    return mapWithSetting(log, truth, key, on ? "true" : "false", alsoOff);
}

/// Generated building 60 toured by B3-sim's stalling robot, seed 1, one scan in three kept (the
/// tour two of the stall rules were traced on), mapped with [GraphSlam] `key` on and off. On,
/// the rule acts (its `count` in the statistics) and the ATE stays below `onBelow` (m); off,
/// it does not, and the ATE exceeds `offAbove` (m), or the tour no longer shows the failure.
/// Each of `alsoOff` is off in both runs: another rule that mends the same tour.
void expectRuleMendsGen60AtAThird(const std::string& key,
                                  std::size_t mapping::SlamStatistics::*count, double onBelow,
                                  double offAbove,
                                  std::initializer_list<const char*> alsoOff = {}) {
    const test::TempDir dir;
    const GeneratedTour tour =
        tourByBenchRobot(dir, 60, simulation::BuildingStyle::Office, "stalling-odometry", 1);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const std::string third = thirdOfTheScans(dir, tour);
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    const FlaggedRun on = mapWithFlag(third, truth, key, true, alsoOff);
    EXPECT_GT(on.statistics.*count, 0u);
    EXPECT_LT(on.ate, onBelow);
    const FlaggedRun off = mapWithFlag(third, truth, key, false, alsoOff);
    EXPECT_EQ(off.statistics.*count, 0u);
    EXPECT_GT(off.ate, offAbove) << "the tour no longer shows the failure";
}

/// Bormann's plan `plan` (a file of ../shared/data) toured by B3-sim's stalling robot, `seed`,
/// at every scan or with one scan in three kept (`atAThird`), mapped with [GraphSlam] `key` off,
/// then on (each of `alsoOff` off in both: another rule that mends the same tour). Off, the rule
/// does not act and the ATE exceeds `offAbove` (m), or the tour no longer shows the failure
/// (`offMessage`); on, it acts (its `count` in the statistics) and the ATE falls below off's
/// divided by `factor`.
void expectRuleMendsStallingPlan(const std::string& plan, int seed, bool atAThird,
                                 const std::string& key,
                                 std::size_t mapping::SlamStatistics::*count, double offAbove,
                                 double factor, const char* offMessage,
                                 std::initializer_list<const char*> alsoOff = {}) {
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "stalling-odometry", seed);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const std::string log = atAThird ? thirdOfTheScans(dir, tour) : tour.log;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    const FlaggedRun off = mapWithFlag(log, truth, key, false, alsoOff);
    EXPECT_EQ(off.statistics.*count, 0u);
    EXPECT_GT(off.ate, offAbove) << offMessage;
    const FlaggedRun on = mapWithFlag(log, truth, key, true, alsoOff);
    EXPECT_GT(on.statistics.*count, 0u);
    EXPECT_LT(on.ate, off.ate / factor);
}

/// The same with one scan in three kept.
void expectRuleMendsStallingPlanAtAThird(const std::string& plan, int seed, const std::string& key,
                                         std::size_t mapping::SlamStatistics::*count,
                                         double offAbove, double factor, const char* offMessage,
                                         std::initializer_list<const char*> alsoOff = {}) {
    expectRuleMendsStallingPlan(plan, seed, true, key, count, offAbove, factor, offMessage,
                                alsoOff);
}

/// Maps `tour` with the shipped configuration and [GraphSlam] `key` on (`onValue`), then off: on,
/// its ATE stays below `onBelow` (m); off, it exceeds `offAbove` (m), or the scenario no longer
/// shows what the setting mends (`offMessage`).
void expectSettingMends(const GeneratedTour& tour, const std::string& key,
                        const std::string& onValue, const std::string& offValue, double onBelow,
                        double offAbove, const char* offMessage) {
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    for (const bool on : {true, false}) {
        SCOPED_TRACE(key + " = " + (on ? onValue : offValue));
        mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
        ini.write("GraphSlam", key, on ? onValue : offValue);
        const mapping::MappingResult result = mapping::mapLog(tour.log, ini);
        ASSERT_EQ(result.trajectory.size(), truth.size());
        const double ate =
            evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth).position.rms;
        if (on)
            EXPECT_LT(ate, onBelow);
        else
            EXPECT_GT(ate, offAbove) << offMessage;
    }
}

/// The same for a [GraphSlam] flag.
void expectSettingMends(const GeneratedTour& tour, const std::string& key, double onBelow,
                        double offAbove, const char* offMessage) {
    expectSettingMends(tour, key, "true", "false", onBelow, offAbove, offMessage);
}

/// The graph SLAM configured from config_ini/toposlam-slam.ini, run over a drive.
struct SlamRun {
    std::unique_ptr<mapping::GraphSlam> slam;
    std::vector<CPose2D> poses;
};

/// `loopThreads`: 0 keeps the file's setting; `adjust` and `adjustMatcher` change the options
/// after loading.
SlamRun runSlam(const test::SimulatedDrive& drive, std::size_t loopThreads = 0,
                const std::function<void(mapping::GraphSlamOptions&)>& adjust = {},
                const std::function<void(matching::GraphMatcherOptions&)>& adjustMatcher = {}) {
    const mrpt::config::CConfigFile ini(test::configIni("toposlam-slam.ini"));
    mapping::GraphSlamOptions options;
    options.loadFromConfigFile(ini, "GraphSlam");
    if (loopThreads > 0)
        options.loopThreads = loopThreads;
    if (adjust)
        adjust(options);
    matching::GraphMatcherOptions matcher;
    matcher.loadFromConfigFile(ini, "GraphScanMatcher");
    if (adjustMatcher)
        adjustMatcher(matcher);
    SlamRun run;
    run.slam = std::make_unique<mapping::GraphSlam>(
        options, matcher, features::makeFeatureExtractor(options.extractor, &ini),
        drive.truth.front());
    for (std::size_t i = 0; i < drive.scans.size(); ++i) {
        std::optional<CPose2D> increment;  // none when the drive has no odometry
        if (i > 0 && !drive.odometry.empty())
            increment = drive.odometry[i] - drive.odometry[i - 1];
        run.slam->processScan(drive.scans[i], increment);
    }
    run.slam->finish();
    for (std::size_t i = 0; i < drive.scans.size(); ++i)
        run.poses.push_back(run.slam->scanPose(i));
    return run;
}

/// A ring corridor 3 m wide around a 14 m x 6 m block, with alcoves and cabinets so that no
/// stretch is a featureless tube.
simulation::PolygonWorld ringCorridor() {
    simulation::PolygonWorld w;
    w.addPolygon({{0, 0}, {20, 0}, {20, 12}, {0, 12}});
    w.addPolygon({{3, 3}, {17, 3}, {17, 9}, {3, 9}});
    for (double x : {5.0, 9.5, 13.0})
        w.addPolygon({{x, 0.01}, {x + 0.8, 0.01}, {x + 0.8, 0.5}, {x, 0.5}});
    for (double x : {6.5, 11.0, 15.5})
        w.addPolygon({{x, 11.5}, {x + 0.6, 11.5}, {x + 0.6, 11.99}, {x, 11.99}});
    for (double y : {4.0, 7.5})
        w.addPolygon({{0.01, y}, {0.4, y}, {0.4, y + 0.9}, {0.01, y + 0.9}});
    for (double y : {5.5})
        w.addPolygon({{19.5, y}, {19.99, y}, {19.99, y + 1.2}, {19.5, y + 1.2}});
    w.addDisc({{10, 1.5}, 0.15});
    return w;
}

/// A lap of ringCorridor() at 0.75 m between scans, each corner turned within one step (as
/// at a third of the scan rate): every corner departs from the last motion by 90 deg.
std::vector<CPose2D> lapWithCornersInOneStep() {
    return test::drivePath({{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 2.5}}, 0.75,
                           1.6);
}

/// The index of the pose of `truth` that turns its n-th corner (n from 1; more than 1 rad in one
/// step), or 0 when there are fewer.
std::size_t cornerScan(const std::vector<CPose2D>& truth, std::size_t n) {
    std::size_t corners = 0;
    for (std::size_t i = 1; i < truth.size(); ++i)
        if (std::abs(mrpt::math::wrapToPi(truth[i].phi() - truth[i - 1].phi())) > 1.0 &&
            ++corners == n)
            return i;
    return 0;
}

/// Marks every reading of `scan` invalid: the laser returned nothing.
void blindScan(mrpt::obs::CObservation2DRangeScan& scan) {
    for (std::size_t b = 0; b < scan.getScanSize(); ++b)
        scan.setScanRangeValidity(b, false);
}

/// Identical offices along a corridor (same size, door, desk), what fools place recognition.
simulation::PolygonWorld identicalRooms(int rooms) {
    simulation::PolygonWorld w;
    const double width = 5.0, length = rooms * width;
    w.addSegment({0, 0}, {length, 0});  // corridor's lower wall
    w.addSegment({0, 0}, {0, 2});       // its ends
    w.addSegment({length, 0}, {length, 2});
    for (int r = 0; r < rooms; ++r) {
        const double x0 = r * width;
        w.addSegment({x0, 2}, {x0 + 1.5, 2});  // wall with a door 1.5 .. 2.5
        w.addSegment({x0 + 2.5, 2}, {x0 + width, 2});
        w.addSegment({x0, 2}, {x0, 6});  // side walls and back wall
        w.addSegment({x0 + width, 2}, {x0 + width, 6});
        w.addSegment({x0, 6}, {x0 + width, 6});
        w.addPolygon({{x0 + 3.2, 4.5}, {x0 + 4.6, 4.5}, {x0 + 4.6, 5.6}, {x0 + 3.2, 5.6}});  // desk
    }
    return w;
}

std::vector<CPose2D> scanTruthOfKeyframes(const mapping::GraphSlam& slam,
                                          const std::vector<CPose2D>& truth) {
    std::vector<CPose2D> out;
    for (const mapping::Keyframe& kf : slam.keyframes())
        out.push_back(truth[kf.scanIndex]);
    return out;
}

/// An office 3 m wide and 4 m deep at x0 (the front wall at y = 2, with a door 1.0 .. 2.0 m
/// along it), its desk in the back corner; `backDoor`: the back wall (y = 6) has one too.
void addNarrowOffice(simulation::PolygonWorld& w, double x0, bool backDoor) {
    const double width = 3.0;
    w.addSegment({x0, 2}, {x0 + 1.0, 2});
    w.addSegment({x0 + 2.0, 2}, {x0 + width, 2});
    if (backDoor) {
        w.addSegment({x0, 6}, {x0 + 1.0, 6});
        w.addSegment({x0 + 2.0, 6}, {x0 + width, 6});
    } else {
        w.addSegment({x0, 6}, {x0 + width, 6});
    }
    w.addSegment({x0, 2}, {x0, 6});
    w.addSegment({x0 + width, 2}, {x0 + width, 6});
    w.addPolygon({{x0 + 2.0, 4.5}, {x0 + 2.8, 4.5}, {x0 + 2.8, 5.6}, {x0 + 2.0, 5.6}});
}

/// `rooms` such offices side by side along a corridor (y 0 .. 2), all alike, so close that
/// the office next door lies inside the loop search's reach (loop_overlap_distance).
simulation::PolygonWorld narrowIdenticalRooms(int rooms) {
    simulation::PolygonWorld w;
    const double length = rooms * 3.0;
    w.addSegment({0, 0}, {length, 0});
    w.addSegment({0, 0}, {0, 2});
    w.addSegment({length, 0}, {length, 2});
    for (int r = 0; r < rooms; ++r)
        addNarrowOffice(w, r * 3.0, false);
    return w;
}

/// The same offices between two corridors (y 0 .. 2 in front, 6 .. 8 behind), each with a
/// back door, the corridors joined beyond the last office (x length .. length + 2).
simulation::PolygonWorld officesBetweenTwoCorridors(int rooms) {
    simulation::PolygonWorld w;
    const double length = rooms * 3.0;
    w.addSegment({0, 0}, {length + 2, 0});
    w.addSegment({0, 0}, {0, 2});
    w.addSegment({length + 2, 0}, {length + 2, 8});
    w.addSegment({0, 8}, {length + 2, 8});
    w.addSegment({0, 6}, {0, 8});
    for (int r = 0; r < rooms; ++r)
        addNarrowOffice(w, r * 3.0, true);
    return w;
}

/// Into the office at x0 from the corridor, round its middle and back out.
void roundNarrowOffice(std::vector<mrpt::math::TPoint2D>& path, double x0) {
    for (const mrpt::math::TPoint2D& p : std::vector<mrpt::math::TPoint2D>{
             {1.5, 1.0}, {1.5, 3.5}, {0.7, 3.5}, {0.7, 5.0}, {1.5, 5.0}, {1.5, 1.0}})
        path.push_back({x0 + p.x, p.y});
}

/// From the start of the corridor, into the first office and round it three times.
std::vector<mrpt::math::TPoint2D> threeVisitsOfTheFirstOffice() {
    std::vector<mrpt::math::TPoint2D> path{{0.8, 1.0}};
    for (int visit = 0; visit < 3; ++visit) {
        if (visit > 0)
            path.push_back({0.8, 1.0});
        roundNarrowOffice(path, 0);
    }
    return path;
}

/// The odometry errors of the identical-room tests (4 % long, 3 % over-turned, 0.003 rad/m).
test::OdometryErrors officeOdometryErrors() {
    test::OdometryErrors errors;
    errors.distanceScale = 1.04;
    errors.turnScale = 1.03;
    errors.headingDriftPerMetre = 0.003;
    return errors;
}

/// A corridor ring of a building's size: 60 x 40 m outside, 2.5 m wide (190 m round its
/// middle), both walls broken by niches and pilasters 0.8-1.6 m wide, 0.3-0.6 m deep, every
/// 5-9 m at random: what a real corridor offers a scan matcher, and look-alike enough.
simulation::PolygonWorld buildingRing() {
    const double width = 60, height = 40, corridor = 2.5;
    simulation::PolygonWorld w;
    w.addPolygon({{0, 0}, {width, 0}, {width, height}, {0, height}});
    w.addPolygon({{corridor, corridor},
                  {width - corridor, corridor},
                  {width - corridor, height - corridor},
                  {corridor, height - corridor}});
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> gap(5.0, 9.0), depth(0.3, 0.6), size(0.8, 1.6);
    for (double x = 3; x < width - 3; x += gap(rng)) {  // bottom and top walls
        const double a = size(rng), d = depth(rng), x2 = x + gap(rng) / 2;
        w.addPolygon({{x, 0.01}, {x + a, 0.01}, {x + a, d}, {x, d}});
        if (x2 < width - 3) {
            w.addPolygon({{x2, height - d},
                          {x2 + a, height - d},
                          {x2 + a, height - 0.01},
                          {x2, height - 0.01}});
        }
    }
    for (double y = 3; y < height - 3; y += gap(rng)) {  // left and right walls
        const double a = size(rng), d = depth(rng), y2 = y + gap(rng) / 2;
        w.addPolygon({{0.01, y}, {d, y}, {d, y + a}, {0.01, y + a}});
        if (y2 < height - 3) {
            w.addPolygon(
                {{width - d, y2}, {width - 0.01, y2}, {width - 0.01, y2 + a}, {width - d, y2 + a}});
        }
    }
    return w;
}

/// Loop edges of `slam` whose measurement is more than 0.3 m from the truth.
std::size_t wrongLoops(const mapping::GraphSlam& slam, const std::vector<CPose2D>& truth) {
    const auto kfTruth = scanTruthOfKeyframes(slam, truth);
    std::size_t wrong = 0;
    for (const auto& e : slam.graph().edges()) {
        if (e.active && e.kind == mapping::EdgeKind::Loop)
            wrong += (e.measurement - (kfTruth[e.to] - kfTruth[e.from])).norm() > 0.3;
    }
    return wrong;
}

}  // namespace

TEST(GraphSlam, ClosesALongLoopAfterOdometryDrift) {
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 1.5}, {10, 1.5}});
    test::OdometryErrors errors;
    errors.distanceScale = 1.03;
    errors.turnScale = 1.03;
    errors.headingDriftPerMetre = 0.006;
    const auto drive = test::simulateDrive(ringCorridor(), truth, errors, 3);
    const double odometryAte = test::absoluteTrajectoryError(truth, drive.odometry);
    ASSERT_GT(odometryAte, 1.0) << "the odometry must drift by metres before the loop closes";

    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    EXPECT_GE(stats.loopsAccepted, 1u) << "the loop is closed";
    EXPECT_GT(stats.registeredShare(), 0.95);
    // 1 cm range noise on ~300 readings per scan: registration is good to a few mm per scan;
    // what remains after the loop is closed is the graph's distortion, a few cm. 0.05 m is 5
    // noise sigmas; without loop closure the ring does not close to that.
    const double ate = test::absoluteTrajectoryError(truth, run.poses);
    EXPECT_LT(ate, 0.05) << "odometry ATE " << odometryAte;
}

TEST(GraphSlam, MapsALaserOnlyLog) {
    // No wheel odometry at all (a laser-only log; MRPT's rawlog-edit --remove-label ODOMETRY
    // makes one of any log): each scan is predicted by the robot's last registered motion.
    // Predicted standing still, a robot doing 0.3 m and up to 17 deg per scan outran ICP
    // (ATE 5.5 m); now 2 mm.
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 1.5}, {10, 1.5}}, 0.3, 0.3);
    auto drive = test::simulateDrive(ringCorridor(), truth, {}, 3);
    drive.odometry.clear();
    const SlamRun run = runSlam(drive);
    EXPECT_EQ(run.slam->statistics().scansWithoutOdometry, drive.scans.size() - 1);
    EXPECT_GT(run.slam->statistics().registeredShare(), 0.95);
    EXPECT_GE(run.slam->statistics().loopsAccepted, 1u);
    // As with odometry (ClosesALongLoopAfterOdometryDrift): 5 noise sigmas.
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
}

TEST(GraphSlam, AnOdometryThatNeverReadsMotionIsNone) {
    // A log recorded without odometry often states zeros instead (CARMEN's FLASER lines,
    // rawlog actions of zero). Taken at its word, the robot stood still while its scans
    // moved: laser-only intel, fr079 and mit-csail written so broke (1.39 / 0.069 / 0.88 m).
    // Read as none, such a log maps exactly as the laser-only log.
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 1.5}, {10, 1.5}}, 0.3, 0.3);
    auto laserOnly = test::simulateDrive(ringCorridor(), truth, {}, 3);
    auto zeros = laserOnly;
    laserOnly.odometry.clear();
    for (CPose2D& o : zeros.odometry)
        o = CPose2D(1.0, -2.0, 0.5);  // constant, not necessarily 0
    const SlamRun a = runSlam(laserOnly), b = runSlam(zeros);
    EXPECT_EQ(b.slam->statistics().scansOfUnmovedOdometry, zeros.scans.size() - 1);
    EXPECT_EQ(b.slam->statistics().scansWithoutOdometry, zeros.scans.size() - 1);
    ASSERT_EQ(a.poses.size(), b.poses.size());
    for (std::size_t i = 0; i < a.poses.size(); ++i) {
        ASSERT_EQ(a.poses[i].x(), b.poses[i].x()) << "scan " << i;
        ASSERT_EQ(a.poses[i].y(), b.poses[i].y()) << "scan " << i;
        ASSERT_EQ(a.poses[i].phi(), b.poses[i].phi()) << "scan " << i;
    }
    EXPECT_LT(test::absoluteTrajectoryError(truth, b.poses), 0.05);

    // An odometry that reads motion from the tenth scan on: only the nine before are none.
    auto lateStart = test::simulateDrive(ringCorridor(), truth, {}, 3);
    for (std::size_t i = 0; i < 10; ++i)
        lateStart.odometry[i] = lateStart.odometry[0];
    ASSERT_NE(lateStart.odometry[10], lateStart.odometry[9]);
    const SlamRun c = runSlam(lateStart);
    EXPECT_EQ(c.slam->statistics().scansOfUnmovedOdometry, 9u);
    EXPECT_EQ(c.slam->statistics().scansWithoutOdometry, 9u);
    EXPECT_LT(test::absoluteTrajectoryError(truth, c.poses), 0.05);
}

TEST(GraphSlam, ClosesTheLoopOfABuildingSizedCorridorRing) {
    // 190 m round a 60 x 40 m corridor ring and on past the start, with odometry that reads 2 %
    // long and drifts 0.003 rad per metre: metres off by the time the robot is back (the
    // Killian-court case: one long loop, corridors only).
    const double middle = 1.25;
    const auto truth = test::drivePath({{middle, middle},
                                        {60 - middle, middle},
                                        {60 - middle, 40 - middle},
                                        {middle, 40 - middle},
                                        {middle, middle},
                                        {20, middle}});
    test::OdometryErrors errors;
    errors.distanceScale = 1.02;
    errors.turnScale = 1.02;
    errors.headingDriftPerMetre = 0.003;
    const auto drive = test::simulateDrive(buildingRing(), truth, errors, 3);
    const double odometryAte = test::absoluteTrajectoryError(truth, drive.odometry);
    ASSERT_GT(odometryAte, 4.0) << "the odometry must be metres off before the loop closes";

    const SlamRun run = runSlam(drive);
    EXPECT_GE(run.slam->statistics().loopsAccepted, 1u) << "the loop is closed";
    EXPECT_EQ(wrongLoops(*run.slam, truth), 0u) << "no niche is taken for a look-alike";
    // Back at the start the two visits are one place: the motion from the first pose to the
    // last is the true one to within a few scans' registration error.
    const CPose2D closure = (run.poses.back() - run.poses.front()) - (truth.back() - truth.front());
    EXPECT_LT(closure.norm(), 0.05);
    // What remains is the graph's distortion: registration errors of a few mm per scan over
    // ~1900 scans add up to ~0.13 m at the far side before the loop, about half after it.
    const double ate = test::absoluteTrajectoryError(truth, run.poses);
    EXPECT_LT(ate, 0.15) << "odometry ATE " << odometryAte;
}

TEST(GraphSlam, AcceptsAgreeingLoopsBeyondTheGate) {
    // Twice round the ring. A fault the front end cannot see on the second lap: the laser
    // drops out for 4 m of the top corridor while the wheels spin (odometry reads 2.5 m too
    // far, in steps too small to count as jumps). The error is far beyond what the drift
    // model's gate expects when the robot is back at the start, so every right loop there is
    // rejected by the gate; matches that agree with each other, from several searches and
    // against both earlier visits of the start, must still close the ring.
    const auto truth = test::drivePath({{1.5, 1.5},
                                        {18.5, 1.5},
                                        {18.5, 10.5},
                                        {1.5, 10.5},
                                        {1.5, 1.5},
                                        {18.5, 1.5},
                                        {18.5, 10.5},
                                        {1.5, 10.5},
                                        {1.5, 1.5},
                                        {18.5, 1.5}});
    auto drive = test::simulateDrive(ringCorridor(), truth, {}, 3);
    std::size_t from = truth.size() / 2;  // second lap, top corridor, 6 m from its start
    while (!(std::abs(truth[from].y() - 10.5) < 1e-9 && truth[from].x() < 12.5))
        ++from;
    const std::size_t to = from + 40;
    ASSERT_NEAR(truth[to].y(), 10.5, 1e-9);
    for (std::size_t i = from; i < to; ++i) {
        auto blind = mrpt::obs::CObservation2DRangeScan::Create(*drive.scans[i]);
        blindScan(*blind);
        drive.scans[i] = blind;
    }
    const double slip = 2.5;
    for (std::size_t i = from; i < drive.odometry.size(); ++i) {
        const double share = std::min(1.0, double(i - from) / double(to - from));
        drive.odometry[i] = CPose2D(drive.odometry[i].x() - share * slip, drive.odometry[i].y(),
                                    drive.odometry[i].phi());
    }
    const auto support = [](std::size_t n) {
        return [n](mapping::GraphSlamOptions& o) { o.loopContestedSupport = n; };
    };
    // Where the laser saw nothing, the truth cannot be recovered: score the other scans.
    const auto seen = [&](const std::vector<CPose2D>& poses) {
        std::vector<CPose2D> out;
        for (std::size_t i = 0; i < poses.size(); ++i)
            if (i < from || i >= to)
                out.push_back(poses[i]);
        return out;
    };
    const SlamRun rejected = runSlam(drive, 0, support(0));
    const double rejectedAte = test::absoluteTrajectoryError(seen(truth), seen(rejected.poses));
    ASSERT_GT(rejectedAte, 0.5) << "the gate must reject the second lap's loops";

    const SlamRun run = runSlam(drive, 0, support(4));
    EXPECT_GE(run.slam->statistics().loopsContested, 4u);
    // As after a normal closure (ClosesALongLoopAfterOdometryDrift): a few cm of distortion.
    const double ate = test::absoluteTrajectoryError(seen(truth), seen(run.poses));
    EXPECT_LT(ate, 0.05) << "without the contested loops: ATE " << rejectedAte;
}

TEST(GraphSlam, SameTrajectoryWhateverTheLoopThreads) {
    // Loop candidates are verified in parallel; the matcher is a pure function of its inputs,
    // so the loops, the graph and every pose must be bit for bit those of one thread.
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 1.5}, {10, 1.5}});
    test::OdometryErrors errors;
    errors.distanceScale = 1.03;
    errors.headingDriftPerMetre = 0.006;
    const auto drive = test::simulateDrive(ringCorridor(), truth, errors, 5);
    const SlamRun one = runSlam(drive, 1), three = runSlam(drive, 3);
    ASSERT_GE(one.slam->statistics().loopCandidates, 10u) << "the parallel path must be used";
    EXPECT_EQ(one.slam->statistics().loopsAccepted, three.slam->statistics().loopsAccepted);
    EXPECT_EQ(one.slam->statistics().loopsUnmatched, three.slam->statistics().loopsUnmatched);
    EXPECT_GT(three.slam->statistics().offloadedSeconds, 0.0);
    ASSERT_EQ(one.poses.size(), three.poses.size());
    for (std::size_t i = 0; i < one.poses.size(); ++i) {
        ASSERT_EQ(one.poses[i].x(), three.poses[i].x()) << "scan " << i;
        ASSERT_EQ(one.poses[i].y(), three.poses[i].y()) << "scan " << i;
        ASSERT_EQ(one.poses[i].phi(), three.poses[i].phi()) << "scan " << i;
    }
}

TEST(GraphSlam, NoWrongLoopBetweenIdenticalRooms) {
    // Along the corridor, into every room and round its desk, then back along the corridor.
    std::vector<mrpt::math::TPoint2D> path{{0.8, 1.0}};
    const int rooms = 5;
    for (int r = 0; r < rooms; ++r) {
        const double x0 = r * 5.0;
        path.push_back({x0 + 2.0, 1.0});
        path.push_back({x0 + 2.0, 3.5});
        path.push_back({x0 + 1.0, 3.5});
        path.push_back({x0 + 1.0, 5.0});
        path.push_back({x0 + 2.0, 5.0});
        path.push_back({x0 + 2.0, 1.0});
    }
    path.push_back({24.2, 1.0});
    path.push_back({0.8, 1.0});
    const auto truth = test::drivePath(path);
    const auto drive = test::simulateDrive(identicalRooms(rooms), truth, officeOdometryErrors(), 5);
    const SlamRun run = runSlam(drive);

    const auto kfTruth = scanTruthOfKeyframes(*run.slam, truth);
    std::size_t loops = 0;
    for (const auto& e : run.slam->graph().edges()) {
        if (!e.active || e.kind != mapping::EdgeKind::Loop)
            continue;
        ++loops;
        const CPose2D actual = kfTruth[e.to] - kfTruth[e.from];
        const CPose2D error = e.measurement - actual;
        EXPECT_LT(error.norm(), 0.3) << "loop " << e.from << " -> " << e.to << " joins the wrong "
                                     << "room: measured " << e.measurement << " true " << actual;
    }
    EXPECT_GT(loops, 0u) << "the way back along the corridor closes loops";
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.1);
}

/// A furnished room (8 x 6 m) opening into a bare corridor 2.5 m wide and 60 m long: along
/// it, nothing within the laser's 20 m fixes the robot until the end wall comes into range.
simulation::PolygonWorld roomAndBareCorridor() {
    simulation::PolygonWorld w;
    w.addSegment({0, 0}, {0, 6});  // the room
    w.addSegment({0, 0}, {8, 0});
    w.addSegment({0, 6}, {8, 6});
    w.addSegment({8, 0}, {8, 2});  // its wall towards the corridor, open from y = 2 to 4.5
    w.addSegment({8, 4.5}, {8, 6});
    w.addSegment({8, 2}, {68, 2});  // the corridor
    w.addSegment({8, 4.5}, {68, 4.5});
    w.addSegment({68, 2}, {68, 4.5});
    w.addPolygon({{1.0, 4.0}, {2.6, 4.0}, {2.6, 5.0}, {1.0, 5.0}});  // desk, cabinet, table
    w.addPolygon({{5.5, 0.3}, {7.5, 0.3}, {7.5, 0.9}, {5.5, 0.9}});
    w.addPolygon({{3.5, 2.5}, {4.5, 2.5}, {4.5, 3.3}, {3.5, 3.3}});
    return w;
}

TEST(GraphSlam, ABareCorridorIsAsLongAsItIsWhenTheOdometryReadsLong) {
    // Round the room twice, then 48 m down the corridor, with odometry that reads 3 % long.
    // Where the scan fixes nothing along the corridor, registration keeps the prediction along
    // it: as read, the map's corridor is 3 % too long. The room's well-registered scans show
    // the odometry's scale, and with it the prediction is right.
    std::vector<mrpt::math::TPoint2D> path;
    for (int lap = 0; lap < 2; ++lap)
        for (const mrpt::math::TPoint2D& p : std::vector<mrpt::math::TPoint2D>{
                 {1.5, 1.5}, {6.5, 1.5}, {6.5, 3.5}, {5.0, 4.5}, {3.0, 4.0}, {1.5, 1.5}})
            path.push_back(p);
    for (const mrpt::math::TPoint2D& p :
         std::vector<mrpt::math::TPoint2D>{{6.5, 1.5}, {6.5, 3.25}, {55, 3.25}})
        path.push_back(p);
    const auto truth = test::drivePath(path);
    test::OdometryErrors errors;
    errors.distanceScale = 1.03;
    errors.turnScale = 1.02;
    const auto drive = test::simulateDrive(roomAndBareCorridor(), truth, errors, 5);

    const auto along = [&](const SlamRun& run) { return run.poses.back().x() - truth.back().x(); };
    const SlamRun asRead = runSlam(drive);  // odometry_calibration is off by default
    const SlamRun calibrated = runSlam(
        drive, 0, [](mapping::GraphSlamOptions& o) { o.odometryCalibration.enabled = true; });
    // ~35 m in the room at 0.1 m steps with 1 cm range noise: the scale to half a per cent.
    EXPECT_NEAR(calibrated.slam->odometryCalibration().scale(), 1 / 1.03, 0.005);
    EXPECT_GT(asRead.slam->statistics().registeredShare(), 0.95);
    // As read, the blind stretch keeps the odometry's 3 %: over a metre (measured 1.19 m).
    EXPECT_GT(std::abs(along(asRead)), 0.6) << "the corridor must be blind for this test";
    // Calibrated: at most the scale's error (0.5 %) over the 48 m and the few cm the way
    // into the corridor costs, 0.35 m (measured 0.29 m, the scale 0.4 % low).
    EXPECT_LT(std::abs(along(calibrated)), 0.35);
}

TEST(GraphSlam, RecoversFromAnOdometryJump) {
    const auto truth = test::drivePath({{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {12, 10.5}});
    test::OdometryErrors errors;
    errors.distanceScale = 1.02;
    errors.jumpAt = truth.size() / 2;
    errors.jump = CPose2D(1.0, 0.0, M_PI / 6);  // 1 m and 30 deg from nowhere
    const auto drive = test::simulateDrive(ringCorridor(), truth, errors, 7);
    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    EXPECT_EQ(stats.odometryJumps, 1u);
    EXPECT_EQ(stats.odometryJumpsBorneOut, 0u) << "the scan does not bear out a glitch";
    EXPECT_GE(stats.registeredByGraphMatcher, 1u) << "the graph matcher registers the jump";
    const CPose2D finalError = run.poses.back() - truth.back();
    EXPECT_LT(finalError.norm(), 0.1);
    EXPECT_LT(std::abs(finalError.phi()), 0.02);
}

TEST(GraphSlam, NoOdometryGlitchIsBorneOut) {
    // The risk of bearing out jumps: a glitch the scan would confirm. Along the corridor,
    // sideways, turned on the spot and both: ICP from the glitched odometry fails the
    // registration's tests here (its correction is too large), and the graph matcher registers
    // the step. (Where ICP from a glitch passes them, the margin decides: next test.)
    const auto truth = test::drivePath({{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {12, 10.5}});
    for (const CPose2D& jump : {CPose2D(0.6, 0, 0), CPose2D(1.0, 0, 0), CPose2D(0.8, 0.3, 0),
                                CPose2D(0, 0, M_PI / 3), CPose2D(1.0, 0, M_PI / 6)}) {
        test::OdometryErrors errors;
        errors.jumpAt = truth.size() / 2;
        errors.jump = jump;
        const SlamRun run = runSlam(test::simulateDrive(ringCorridor(), truth, errors, 7));
        const auto& stats = run.slam->statistics();
        EXPECT_EQ(stats.odometryJumps, 1u) << jump;
        EXPECT_EQ(stats.odometryJumpsBorneOut, 0u) << jump;
        // 1 cm range noise: a few mm (measured 3 mm), 0.05 m as in the loop test.
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05) << jump;
    }
}

/// From the room down the corridor of `world`, `step` m between scans, with an odometry that
/// stalls for two scans (repeats its reading) once the robot passes x = 25 m: the drive, and
/// the stall's first scan.
std::pair<test::SimulatedDrive, std::size_t> stallDownTheCorridor(
    const simulation::PolygonWorld& world, double step) {
    const auto truth = test::drivePath({{1.5, 1.5}, {6.5, 1.5}, {6.5, 3.25}, {45, 3.25}}, step);
    std::size_t stall = 0;
    while (truth[stall].x() < 25)
        ++stall;
    auto drive = test::simulateDrive(world, truth, {}, 31);
    drive.odometry[stall] = drive.odometry[stall + 1] = drive.odometry[stall - 1];
    return {std::move(drive), stall};
}

TEST(GraphSlam, AnOdometryStallAlongABareCorridorIsBridged) {
    // Down a corridor whose walls fix nothing along it, 0.3 m between scans, the odometry
    // stalls for two scans (it repeats its reading) and the next reading carries all three
    // steps. ICP keeps the stall's standstill for its two scans; the reading after it, less
    // that standstill, is the step (bridge_odometry_stalls), and the stall's two scans are
    // placed between. Predicted by the last motion instead (a standstill), the robot would
    // lose the stall's 0.9 m for good.
    const auto stalled = stallDownTheCorridor(roomAndBareCorridor(), 0.3);
    const test::SimulatedDrive& drive = stalled.first;
    const std::size_t stall = stalled.second;  // (a lambda may not capture a binding in C++17)
    const auto& truth = drive.truth;
    const auto along = [&](const SlamRun& run) { return run.poses.back().x() - truth.back().x(); };

    // Registration from the standstill only, so that the stall's scans stay behind (here the
    // scans do not change along the corridor, so predict_stalls_by_last_motion would not
    // start them from the last motion either; the next test).
    const auto fromStandstill = [](mapping::GraphSlamOptions& o) {
        o.predictStallsByLastMotion = false;
    };
    const SlamRun run = runSlam(drive, 0, fromStandstill);
    EXPECT_EQ(run.slam->statistics().odometryStallsBridged, 1u);
    EXPECT_EQ(run.slam->statistics().stalledScansPlaced, 2u);
    EXPECT_EQ(run.slam->statistics().registrationFailed, 0u);
    EXPECT_LT(std::abs(along(run)), 0.1);
    // Where the robot was during the stall (left behind, they would be 0.3 and 0.6 m short).
    for (const std::size_t i : {stall, stall + 1})
        EXPECT_LT(std::abs(run.poses[i].x() - truth[i].x()), 0.1) << "scan " << i;
    const SlamRun unbridged = runSlam(drive, 0, [&](mapping::GraphSlamOptions& o) {
        fromStandstill(o);
        o.bridgeOdometryStalls = false;
    });
    EXPECT_LT(along(unbridged), -0.5) << "the corridor must be blind for this test";
}

/// The room and corridor above, with a pillar (0.3 m square) against the corridor's far wall
/// every 3 m: a moving robot sees them move between scans, but from where a stalled
/// odometry leaves it they are too far off for ICP to pull the scan along.
simulation::PolygonWorld roomAndCorridorWithPillars() {
    simulation::PolygonWorld w = roomAndBareCorridor();
    for (double x = 10; x < 66; x += 3)
        w.addPolygon({{x, 4.2}, {x + 0.3, 4.2}, {x + 0.3, 4.5}, {x, 4.5}});
    return w;
}

TEST(GraphSlam, AnOdometryStallIsPredictedByTheLastMotionWhereTheScanChanged) {
    // Down the corridor with pillars, 0.6 m between scans (a fast robot), the odometry stalls
    // for two scans (it repeats its reading). The scans change (the pillars move by), so this
    // is no stop: ICP also starts them from the last motion (predict_stalls_by_last_motion),
    // fits them better there, and they are where the robot was. From the standstill the
    // pillars are beyond ICP's reach, and the stall's scans, keyframes, stay behind.
    const auto stalled = stallDownTheCorridor(roomAndCorridorWithPillars(), 0.6);
    const test::SimulatedDrive& drive = stalled.first;
    const std::size_t stall = stalled.second;
    const auto& truth = drive.truth;
    const auto stallError = [&](const SlamRun& run) {
        double worst = 0;
        for (const std::size_t i : {stall, stall + 1, stall + 2})
            worst = std::max(worst, std::abs(run.poses[i].x() - truth[i].x()));
        return worst;
    };
    const SlamRun run = runSlam(drive);
    EXPECT_GE(run.slam->statistics().lastMotionPredictions, 2u);
    EXPECT_EQ(run.slam->statistics().registrationFailed, 0u);
    EXPECT_LT(stallError(run), 0.05);
    EXPECT_LT(std::abs(run.poses.back().x() - truth.back().x()), 0.05);
    const SlamRun fromStandstill = runSlam(
        drive, 0, [](mapping::GraphSlamOptions& o) { o.predictStallsByLastMotion = false; });
    EXPECT_GT(stallError(fromStandstill), 0.5) << "ICP must not reach the pillars for this test";
}

TEST(GraphSlam, ARobotThatStopsInABareCorridorIsNotPredictedToDriveOn) {
    // A robot that stops reads the same zero as an odometry that stalled. Down the bare
    // corridor of the tests above it stands for ten scans, then drives on. Its scans do not
    // change, so the stop is not predicted by the last motion: that would carry the robot on
    // along the corridor, 0.3 m a scan, where nothing in the scan holds it back.
    auto truth = test::drivePath({{1.5, 1.5}, {6.5, 1.5}, {6.5, 3.25}, {45, 3.25}}, 0.3);
    std::size_t stop = 0;
    while (truth[stop].x() < 25)
        ++stop;
    truth.insert(truth.begin() + long(stop), 10, truth[stop]);
    const auto drive = test::simulateDrive(roomAndBareCorridor(), truth, {}, 37);
    const SlamRun run = runSlam(drive);
    EXPECT_EQ(run.slam->statistics().lastMotionPredictions, 0u);
    // The step after the stop is bridged as a stall's catch-up and the stop's scans are spread
    // over it (bridge_odometry_stalls): off by up to that one step, 0.3 m, not by ten.
    for (const std::size_t i : {stop, stop + 5, stop + 10, stop + 11})
        EXPECT_LT(std::abs(run.poses[i].x() - truth[i].x()), 0.3) << "scan " << i;
    EXPECT_LT(std::abs(run.poses.back().x() - truth.back().x()), 0.1);
}

TEST(GraphSlam, AGlitchAlongABareCorridorIsNotBorneOut) {
    // Down a corridor whose walls fix nothing along it, the odometry jumps 0.6 m ahead. ICP
    // from there passes every test (it does not move along the corridor) and fits the scan as
    // well as ICP from the last motion: no clear margin, so the jump stays a jump and the
    // robot keeps its last motion. Taken, it would leave the rest of the corridor 0.6 m ahead.
    const auto truth = test::drivePath({{1.5, 1.5}, {6.5, 1.5}, {6.5, 3.25}, {45, 3.25}});
    std::size_t mid = 0;
    while (truth[mid].x() < 25)
        ++mid;
    test::OdometryErrors errors;
    errors.jumpAt = mid;
    errors.jump = CPose2D(0.6, 0, 0);
    const SlamRun run = runSlam(test::simulateDrive(roomAndBareCorridor(), truth, errors, 5));
    const auto& stats = run.slam->statistics();
    ASSERT_EQ(stats.odometryJumps, 1u);
    EXPECT_EQ(stats.odometryJumpsBorneOut, 0u);
    EXPECT_LT(std::abs(run.poses.back().x() - truth.back().x()), 0.3);
}

TEST(GraphSlam, AFastTurnAtALowScanRateIsBorneOutNotAJump) {
    // 0.75 m between scans and each corner turned within one step: every corner departs from
    // the last motion (straight on) by 90 deg and the step after it by as much again, beyond
    // the jump bounds, yet the odometry is right. ICP from it fits the scan where ICP from the
    // last motion does not, so each such step is predicted by the odometry and registered.
    const auto truth = lapWithCornersInOneStep();
    const auto drive = test::simulateDrive(ringCorridor(), truth, {}, 23);
    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    ASSERT_GE(stats.odometryJumps, 3u) << "the corners must look like jumps for this test";
    EXPECT_EQ(stats.odometryJumpsBorneOut, stats.odometryJumps);
    EXPECT_EQ(stats.registrationFailed, 0u);
    // 1 cm range noise: registration to a few mm per scan, 0.05 m as in the loop test.
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
}

TEST(GraphSlam, AJumpNothingRegistersKeepsTheReadingWhereTheLogsJumpsWereTheOdometrys) {
    // As above, every corner turned within one 0.75 m step, each a jump the scan bears out;
    // then at the third corner the laser returns nothing (blinded for a moment), so neither
    // ICP nor the graph matcher can place the scan. The log's jumps so far were all the
    // odometry's own steps: the scan keeps the reading, not the last motion (straight on, 90 deg
    // off), as a tour logged at a third of its scan rate needs (gen61, URG-04LX, B3-sim: a corner
    // kept at the last motion left the rest of the tour 0.96 m off).
    const auto truth = lapWithCornersInOneStep();
    auto drive = test::simulateDrive(ringCorridor(), truth, {}, 23);
    const std::size_t blind = cornerScan(truth, 3);
    ASSERT_GT(blind, 0u);
    blindScan(*drive.scans[blind]);
    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    ASSERT_GE(stats.registrationFailed, 1u) << "the blinded scan must not register";
    EXPECT_EQ(stats.odometryJumpReadingsKept, 1u);
    // Its pose relative to the scan before it: the odometry's step is exact here, and the scan
    // before it is registered to a few mm.
    const CPose2D truthStep = truth[blind] - truth[blind - 1];
    const CPose2D step = run.poses[blind] - run.poses[blind - 1];
    EXPECT_LT((step - truthStep).norm(), 0.05);
    EXPECT_LT(std::abs(mrpt::math::wrapToPi(step.phi() - truthStep.phi())), mrpt::DEG2RAD(2.0));
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
}

TEST(GraphSlam, AJumpedReadingLongerThanTheRobotStepsIsNotKeptWhereNothingRegisters) {
    // The same drive and log prior as above, but the blinded scan is on a straight stretch and
    // its odometry jumps 0.8 m ahead (a glitch, or a stall caught up in one step): 1.55 m where
    // the robot never stepped more than 0.75 m. That is no step of this robot: the scan keeps
    // the last motion, which is the robot's.
    const auto truth = lapWithCornersInOneStep();
    ASSERT_GT(cornerScan(truth, 2), 0u);
    const std::size_t blind = cornerScan(truth, 2) + 4;
    // The odometry frame jumps 0.8 m along the robot's heading there.
    const double heading = truth[blind].phi();
    test::OdometryErrors errors;
    errors.jumpAt = blind;
    errors.jump = CPose2D(0.8 * std::cos(heading), 0.8 * std::sin(heading), 0);
    auto drive = test::simulateDrive(ringCorridor(), truth, errors, 23);
    blindScan(*drive.scans[blind]);
    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    ASSERT_GE(stats.registrationFailed, 1u) << "the blinded scan must not register";
    EXPECT_EQ(stats.odometryJumpReadingsKept, 0u);
    const CPose2D truthStep = truth[blind] - truth[blind - 1];
    const CPose2D step = run.poses[blind] - run.poses[blind - 1];
    EXPECT_LT((step - truthStep).norm(), 0.05);
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
}

TEST(GraphSlam, LongStepsOfAPoorOdometryAreNotTakenForJumps) {
    // 1.1 m and up to 45 deg between scans (a tour logged at a third of its scan rate), an
    // odometry 5 % long, turning 6 % too far and curving 3 deg per metre, and an 8 m laser.
    // Corners depart from the last motion by more than the jump bounds, and the odometry's
    // step there is off sideways by more than max_lateral_correction allows a short step; the
    // scan must still choose the odometry's step over the last motion (which turned 45 deg
    // less or more), and no look-alike of the graph matcher's. Several seeds: the laser noise
    // decides which of these a corner meets.
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 2.5}, {10, 1.5}}, 1.1, 0.8);
    test::OdometryErrors errors;
    errors.distanceScale = 1.05;
    errors.turnScale = 1.06;
    errors.headingDriftPerMetre = mrpt::DEG2RAD(3.0);
    simulation::LaserModel laser;
    laser.maxRange = 8;
    for (unsigned seed = 31; seed < 39; ++seed) {
        const SlamRun run =
            runSlam(test::simulateDrive(ringCorridor(), truth, errors, seed, laser));
        const auto& stats = run.slam->statistics();
        ASSERT_GE(stats.odometryJumps, 3u) << "the corners must look like jumps for this test";
        // 1 cm range noise: a few cm per scan at these steps (measured 0.025-0.084 m); a corner
        // kept at the last motion or the matcher's look-alike leaves the rest of the lap
        // 0.4 m off (as before session 70, on six of these seeds).
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.15) << "seed " << seed;
    }
}

TEST(GraphSlam, OdometryCatchingUpAfterAStallIsNotThePrediction) {
    // The odometry stops updating for six scans while the robot turns on the spot at a corner
    // (as in logs that repeat the last odometry message), then reports the whole turn so far in
    // one step: 40 deg (seven steps) where the robot turned 6, within the jump bounds (45 deg) but
    // more than ICP may correct (20 deg). Taken for the prediction, ICP's answer is rejected and
    // the graph matcher has to register the scan; OdometryLag predicts the last registered motion
    // and ICP registers it. (ICP saw the robot move during the stall, its last 0.1 m to the
    // corner, so the stall is not bridged; bridge_stall_and_step, off here, bridges it: the
    // reading is the stall as registered plus a step that turns as the last motion did.)
    const auto truth = test::drivePath({{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}}, 0.1, 0.1);
    auto drive = test::simulateDrive(ringCorridor(), truth, {}, 17);
    std::size_t turnStart = 1;
    while (std::abs(mrpt::math::wrapToPi(truth[turnStart].phi() - truth[0].phi())) < 1e-9)
        ++turnStart;
    for (std::size_t k = turnStart; k < turnStart + 6; ++k)
        drive.odometry[k] = drive.odometry[turnStart - 1];
    for (const bool byLength : {false, true}) {
        SCOPED_TRACE(byLength ? "bridge_stall_and_step" : "catch-up");
        const SlamRun run = runSlam(
            drive, 0, [&](mapping::GraphSlamOptions& o) { o.bridgeStallAndStep = byLength; });
        const auto& stats = run.slam->statistics();
        EXPECT_EQ(stats.odometryCatchUps, byLength ? 0u : 1u);
        EXPECT_EQ(stats.odometryStallsBridged, byLength ? 1u : 0u);
        EXPECT_EQ(stats.odometryStallsAndStepBridged, byLength ? 1u : 0u);
        EXPECT_EQ(stats.odometryJumps, 0u);
        EXPECT_EQ(stats.registeredByGraphMatcher, 0u);
        EXPECT_EQ(stats.registrationFailed, 0u);
        const CPose2D atCatchUp = run.poses[turnStart + 6] - truth[turnStart + 6];
        EXPECT_LT(std::abs(atCatchUp.phi()), mrpt::DEG2RAD(1.0));
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
    }
}

TEST(GraphSlam, ATurnOnTheSpotDuringAStallIsBoundedFromTheStandstill) {
    // 1.05 m between scans (a log at a third of its scan rate); at each corner the robot turns
    // 45 deg as it drives into it and 45 more on the spot, and at the first turn on the spot
    // the odometry stalls (repeats its reading). The stall is predicted by the last motion
    // (1.05 m on, turning 45 deg) or the standstill, and ICP from either ends off the turn;
    // the graph matcher finds it, beyond twice the jump bounds from the last motion, a
    // look-alike's distance, but a turn on the spot from where the odometry stalled, which in
    // a stall is as good a guess. Refused, the scan kept the last motion and the rest of the
    // lap followed it, 0.5 m ATE (Bormann's NLB at a third of its scans: 10 m).
    const auto truth = test::drivePath(
        {{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 2.5}}, 1.05, 0.8);
    std::size_t turn = 1;  // the step into the corner, then the turn on the spot
    while (std::abs(mrpt::math::wrapToPi(truth[turn].phi() - truth[0].phi())) < 1e-9)
        ++turn;
    ++turn;
    ASSERT_LT((truth[turn] - truth[turn - 1]).norm(), 1e-9);
    for (unsigned seed = 41; seed < 45; ++seed) {
        auto drive = test::simulateDrive(ringCorridor(), truth, {}, seed);
        drive.odometry[turn] = drive.odometry[turn - 1];
        const SlamRun run = runSlam(drive);
        const double headingError = std::abs((run.poses[turn] - truth[turn]).phi());
        EXPECT_LT(headingError, mrpt::DEG2RAD(2.0)) << "seed " << seed;
        // 1 cm range noise: registration to a few mm per scan, 0.05 m as in the loop test.
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05) << "seed " << seed;
    }
}

TEST(GraphSlam, ATurnOnTheSpotSoonAfterAStallIsTheOdometrysNotACatchUp) {
    // 1.05 m between scans; the odometry stalls for a scan on the way to the first corner,
    // and two scans after it the robot turns on the spot by 40 deg, twice. The odometry reads
    // those turns right, but so soon after a stall a step that turns 40 deg more than the
    // last motion was taken for catching up (OdometryLag), and the last motion, 1.05 m on,
    // predicted: ICP from there fails, and the graph matcher's answer is beyond twice the jump
    // bounds from it. Without a rule the scan kept the last motion, 1.05 m and 40 deg off
    // (Bormann's lab_b at a third of its scans, 8.5 m ATE). First ICP from the odometry's
    // step placed it (keepCaughtUpReading); now the reading after the stall (2.1 m, a jump)
    // has delivered the stall's 1.05 m, the catch-up is over, and the turn is the odometry's.
    std::vector<CPose2D> truth = test::drivePath({{1.5, 1.5}, {18.5, 1.5}}, 1.05);
    const std::size_t stall = truth.size() - 2, turned = truth.size();
    for (const double deg : {40.0, 80.0})
        truth.emplace_back(18.5, 1.5, mrpt::DEG2RAD(deg));
    const auto onward =
        test::drivePath({{18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 2.5}}, 1.05, 0.8);
    truth.insert(truth.end(), onward.begin(), onward.end());
    for (unsigned seed = 51; seed < 55; ++seed) {
        auto drive = test::simulateDrive(ringCorridor(), truth, {}, seed);
        drive.odometry[stall] = drive.odometry[stall - 1];
        const SlamRun run = runSlam(drive);
        const auto& stats = run.slam->statistics();
        EXPECT_EQ(stats.odometryCatchUps, 0u) << "the stall's motion was delivered: seed " << seed;
        const double headingError = std::abs((run.poses[turned] - truth[turned]).phi());
        EXPECT_LT(headingError, mrpt::DEG2RAD(2.0)) << "seed " << seed;
        // 1 cm range noise: registration to a few mm per scan, 0.05 m as in the loop test.
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05) << "seed " << seed;
    }
}

TEST(GraphSlam, ATurnTheOdometryOvershotIsFoundBetweenItAndTheLastMotion) {
    // 0.4 m between scans; at the first corner the robot turns 15, 60 and 15 deg in three
    // scans, and the odometry reads the 60 deg step as 84 (it stalled and caught up past the
    // turn, as mit-csail's does at a quarter of its scans). That step departs from the last
    // motion (15 deg) by more than the jump bounds (45 deg), and ICP from the odometry's step,
    // 24 deg off, would correct it by more than it may (20 deg). Here the graph matcher finds
    // the turn; where it finds nothing (mit-csail's scan had too few segments), ICP from starts
    // between the last motion and the odometry's step does. Without either the scan keeps the
    // last motion.
    std::vector<CPose2D> truth = test::drivePath({{1.5, 1.5}, {18.5, 1.5}}, 0.4);
    truth.emplace_back(18.5, 1.5, mrpt::DEG2RAD(15.0));
    const std::size_t overshot = truth.size();
    truth.emplace_back(18.5, 1.5, mrpt::DEG2RAD(75.0));
    const auto onward = test::drivePath({{18.5, 1.5}, {18.5, 10.5}, {12, 10.5}}, 0.4);
    truth.insert(truth.end(), onward.begin(), onward.end());
    auto drive = test::simulateDrive(ringCorridor(), truth, {}, 29);
    // That step reads 24 deg more; every other step as it was.
    const CPose2D atStep = drive.odometry[overshot];
    for (std::size_t i = overshot; i < drive.odometry.size(); ++i)
        drive.odometry[i] =
            atStep + CPose2D(0, 0, mrpt::DEG2RAD(24.0)) + (drive.odometry[i] - atStep);
    const auto turnError = [&](const SlamRun& run) {
        return std::abs((run.poses[overshot] - truth[overshot]).phi());
    };

    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    ASSERT_EQ(stats.odometryJumps, 1u) << "the overshot step must look like a jump";
    EXPECT_EQ(stats.odometryJumpsBorneOut, 0u);
    EXPECT_EQ(stats.odometryJumpsBetween, 0u) << "the graph matcher placed it";
    EXPECT_LT(turnError(run), mrpt::DEG2RAD(1.0));

    const auto noMatch = [](matching::GraphMatcherOptions& m) { m.minInlierRatio = 1.1; };
    const SlamRun matcherless = runSlam(drive, 0, {}, noMatch);
    EXPECT_EQ(matcherless.slam->statistics().odometryJumpsBetween, 1u);
    EXPECT_LT(turnError(matcherless), mrpt::DEG2RAD(1.0));

    const SlamRun neither = runSlam(
        drive, 0, [](mapping::GraphSlamOptions& o) { o.jumpSearchStep = 0; }, noMatch);
    EXPECT_GE(neither.slam->statistics().registrationFailed, 1u);
    EXPECT_GT(turnError(neither), mrpt::DEG2RAD(40.0)) << "the last motion, 45 deg short";
}

TEST(GraphSlam, LongStepsOfAFastRobotAreNotJumps) {
    // 0.6 m and up to 0.5 rad between scans (a robot at 1.2 m/s with a 2 Hz laser, or a log
    // thinned to a third): every step is beyond the jump bounds (0.5 m), but each is the motion
    // the last one predicts, so the odometry is the prediction and ICP registers the scans.
    // (Judged on the step alone, every one was a jump: the last motion predicted, the graph
    // matcher registered.)
    const auto truth =
        test::drivePath({{1.5, 1.5}, {18.5, 1.5}, {18.5, 10.5}, {1.5, 10.5}, {1.5, 3}}, 0.6, 0.5);
    test::OdometryErrors errors;
    errors.distanceScale = 1.02;
    const auto drive = test::simulateDrive(ringCorridor(), truth, errors, 13);
    const SlamRun run = runSlam(drive);
    const auto& stats = run.slam->statistics();
    // Setting off at full speed after turning on the spot departs from the last motion (a turn
    // in place) by a whole step: at most the 4 corners (judged on the step alone: 84 of the 93).
    EXPECT_LE(stats.odometryJumps, 4u);
    EXPECT_GT(double(stats.registeredByIcp), 0.9 * double(stats.scans - 1));
    // As in RecoversFromAnOdometryJump: a few cm over the drive.
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.05);
    const CPose2D finalError = run.poses.back() - truth.back();
    EXPECT_LT(finalError.norm(), 0.1);
    EXPECT_LT(std::abs(finalError.phi()), 0.02);
}

TEST(GraphSlam, ReversingIsNotTakenForDrivingForward) {
    // Odometry that counts reversing as driving forward (fr079's), at 0.3 m per scan (fr079 at a
    // third of its scan rate): each reversing step is predicted 0.6 m off, more than ICP
    // reaches or may correct and than a step may be. At the first one the graph matcher finds
    // the true step and ICP on the submap confirms it; then the last motion is the better
    // prediction (both confirm_large_corrections). Without that, ICP from the odometry either
    // fails, keeping the odometry's step, or is held at the odometry's position along the
    // corridor.
    constexpr double kStep = 0.3;
    std::vector<CPose2D> truth = test::drivePath({{1.5, 1.5}, {18, 1.5}}, kStep);
    for (int k = 1; k <= 10; ++k)  // 3 m backwards from the corridor's end, facing it
        truth.emplace_back(truth.back().x() - kStep, 1.5, truth.back().phi());
    const auto onward =
        test::drivePath({{truth.back().x(), 1.5}, {18.5, 1.5}, {18.5, 10.5}, {12, 10.5}}, kStep);
    truth.insert(truth.end(), onward.begin() + 1, onward.end());
    test::OdometryErrors errors;
    errors.reversingReadsForward = true;
    const auto drive = test::simulateDrive(ringCorridor(), truth, errors, 11);
    const CPose2D odometryEnd = truth.front() + drive.odometry.back();  // the truth's frame
    ASSERT_GT((odometryEnd - truth.back()).norm(), 5.0)
        << "the odometry must be metres off after reversing";

    const SlamRun run = runSlam(drive);
    const CPose2D finalError = run.poses.back() - truth.back();
    // Registered steps, as in RecoversFromAnOdometryJump: a few cm over the drive.
    EXPECT_LT(finalError.norm(), 0.1);
    EXPECT_LT(std::abs(finalError.phi()), 0.02);
    const auto& stats = run.slam->statistics();
    EXPECT_GE(stats.graphMatcherConfirmed, 1u) << "the first reversing step";
    EXPECT_GE(stats.lastMotionPredictions, 1u) << "the next ones";
    EXPECT_EQ(stats.registrationFailed, 0u);

    const SlamRun unconfirmed =
        runSlam(drive, 0, [](mapping::GraphSlamOptions& o) { o.confirmLargeCorrections = false; });
    EXPECT_GT((unconfirmed.poses.back() - truth.back()).norm(), 1.0)
        << "without it the reversing steps must keep the odometry's";
    EXPECT_EQ(unconfirmed.slam->statistics().graphMatcherConfirmed +
                  unconfirmed.slam->statistics().lastMotionPredictions,
              0u);
}

TEST(GraphSlam, NoHalfTurnFromALookAlikeMatchAmongPeople) {
    // The project's office toured with six people walking about (toposlam-sim --tour --people 6
    // --seed 2). Where they hide the walls ICP gives up, and the graph matcher, retrying without
    // a guess, matched a stretch of corridor seen the other way round: taken as the motion,
    // it turned the rest of the map by 180 deg (trajectory error 6.4 m). Unless the odometry
    // jumped, a correction it would have counted as a jump is no registration.
    const test::TempDir dir;
    const simulation::SimulationJob job = simulateOfficeTourWithPeople(dir.path());
    const mapping::MappingResult result = mapping::mapLog(
        job.rawlogPath, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    const io::Trajectory2D truth = io::loadTrajectory(job.groundTruthPath);
    ASSERT_GT(truth.size(), 300u);
    ASSERT_EQ(result.trajectory.size(), truth.size());
    // Heading error of every pose relative to every other (the map frame's own turn cancels).
    std::vector<double> offset;
    for (std::size_t i = 0; i < truth.size(); ++i)
        offset.push_back(result.trajectory[i].pose.phi - truth[i].pose.phi);
    double worst = 0;
    for (std::size_t i = 0; i < offset.size(); ++i) {
        for (std::size_t j = i + 1; j < offset.size(); ++j)
            worst = std::max(worst, std::abs(std::remainder(offset[j] - offset[i], 2 * M_PI)));
    }
    // People pull ICP along corridors by decimetres, never by more than a few degrees.
    EXPECT_LT(worst, mrpt::DEG2RAD(10.0));
}

TEST(GraphSlam, APersonWalkingAheadDoesNotHoldTheRobotBack) {
    // The office toured with six people walking about (seed 2). One keeps a step ahead of the
    // robot along a corridor: in each keyframe it stands where the robot's next scan sees it, so
    // ICP took back nearly every step (trajectory error 0.55 m, against 0.07 m for MRPT's ICP
    // engine). At the shipped settings the foreground check registers those scans again without
    // the small objects close to the laser (foreground_check); with the ini's "crowded places"
    // settings instead (icp_min_views = 2) ICP's first stage matches only submap points seen
    // from two keyframes. Either way the person no longer holds the robot back.
    const test::TempDir dir;
    const simulation::SimulationJob job = simulateOfficeTourWithPeople(dir.path());
    const io::Trajectory2D truth = io::loadTrajectory(job.groundTruthPath);
    const auto mapWith = [&](const std::function<void(mrpt::config::CConfigFileBase&)>& adjust) {
        mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
        adjust(ini);
        return mapping::mapLog(job.rawlogPath, ini);
    };
    const auto ateOf = [&](const mapping::MappingResult& result) {
        EXPECT_EQ(result.trajectory.size(), truth.size());
        const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
        EXPECT_EQ(ate.matchedPoses, truth.size());
        return ate.position.rms;
    };
    // Without people the office maps to 0.015 m; the ICP engine gets 0.07 m among them.
    const mapping::MappingResult shipped = mapWith([](auto&) {});
    EXPECT_LT(ateOf(shipped), 0.1);
    ASSERT_TRUE(shipped.statistics);
    EXPECT_GT(shipped.statistics->icpWithoutForeground, 0u) << "the check found the person";
    const mapping::MappingResult crowded = mapWith([](mrpt::config::CConfigFileBase& ini) {
        ini.write("GraphSlam", "foreground_check", 0);
        ini.write("GraphSlam", "icp_min_views", 2);  // the ini's "crowded places" settings
        ini.write("GraphSlam", "icp_max_incidence_deg", 80);
    });
    EXPECT_LT(ateOf(crowded), 0.1);
}

TEST(GraphSlam, WithoutThePersonAheadICPDoesNotSlideAlongTheCorridor) {
    // The office with ten people walking about (seed 2). At t = 1700000218 s ICP pushed the
    // robot 0.42 m ahead; without the person's readings it still slid 0.26 m along a corridor
    // whose walls fix nothing along it (trajectory error 0.41 m). The rest of the scan fits as
    // well where the odometry puts the robot along the corridor, so that position is kept.
    const test::TempDir dir;
    simulation::SimulatorConfig config;
    config.log.people.count = 10;
    config.log.seed = 2;
    const simulation::SimulationJob job = simulateOfficeTour(config, dir.path());
    const mapping::MappingResult result = mapping::mapLog(
        job.rawlogPath, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    const io::Trajectory2D truth = io::loadTrajectory(job.groundTruthPath);
    ASSERT_EQ(result.trajectory.size(), truth.size());
    const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
    EXPECT_LT(ate.position.rms, 0.2);  // 0.13 m; MRPT's ICP engine 0.07 m
}

TEST(GraphSlam, AnAnswerOutrunsTheOdometryBeyondTenSigmaOfItsModel) {
    // The chi-square of a correction under the odometry model of the step: 0.33 m and 10 deg
    // of odometry give sigmas of 0.037 m and 2.0 deg (toposlam-slam.ini); unsettled ICP that
    // lands beyond unsettled_max_chi2 (100: ten sigmas) counts only where some start settled.
    const mrpt::config::CConfigFile ini(test::configIni("toposlam-slam.ini"));
    mapping::GraphSlamOptions options;
    options.loadFromConfigFile(ini, "GraphSlam");
    ASSERT_EQ(options.unsettledMaxChi2, 100);
    matching::GraphMatcherOptions matcher;
    mapping::Prediction prediction;
    prediction.odometryPredicted = true;
    prediction.odometryStep = CPose2D(0.33, 0.02, mrpt::DEG2RAD(10.0));
    prediction.inSubmap = CPose2D(4, -1, 0.3);
    const auto corrected = [&](double x, double y, double phiDeg) {
        return prediction.inSubmap + CPose2D(x, y, mrpt::DEG2RAD(phiDeg));
    };
    const mapping::ScanRegistration registration(options, matcher);
    // The correction seen among people: 0.30 m ahead and 17 deg more turn (chi-square 142).
    EXPECT_TRUE(registration.outrunsOdometry(prediction, corrected(0.30, -0.04, 17.3)));
    EXPECT_TRUE(registration.outrunsOdometry(prediction, corrected(0, 0, -25)));
    EXPECT_TRUE(registration.outrunsOdometry(prediction, corrected(0.45, 0, 0)));
    // What real odometry gets wrong in one step (mit-csail: 14-16 deg; fr079, reversing: 0.24 m
    // behind its 0.14 m step, chi-square 80) stays within, and so do centimetres and degrees.
    EXPECT_FALSE(registration.outrunsOdometry(prediction, corrected(0, 0, -16)));
    EXPECT_FALSE(registration.outrunsOdometry(prediction, corrected(-0.25, 0, 0)));
    EXPECT_FALSE(registration.outrunsOdometry(prediction, corrected(0.1, -0.03, -1.5)));
    // The last motion predicted (a jump, a stall, no odometry): nothing bounds the correction.
    prediction.odometryPredicted = false;
    EXPECT_FALSE(registration.outrunsOdometry(prediction, corrected(0.30, -0.04, 17.3)));
    // Off.
    prediction.odometryPredicted = true;
    options.unsettledMaxChi2 = 0;
    const mapping::ScanRegistration off(options, matcher);
    EXPECT_FALSE(off.outrunsOdometry(prediction, corrected(0.30, -0.04, 17.3)));
}

TEST(GraphSlam, PeopleCrowdingTheLaserDoNotTurnTheMap) {
    // Bormann's Freiburg79 (furnished) toured with 15 people walking about, as B3-sim's
    // "people" robot (toposlam-bench-slam --sim-plans Freiburg79_scan --sim-robots people
    // --sim-seeds 3). At one scan ICP did not settle and ended 0.30 m ahead and 17 deg turned
    // where the odometry had the step within 1.5 deg; from the other starts it settled nowhere
    // either. Taken, it turned the rest of the map (trajectory error 0.34 m, worst relation
    // 1.66 m). Far beyond the odometry's noise (unsettled_max_chi2) such an answer is refused:
    // 0.12 m (the worst relation left, 0.67 m, is a second start 0.28 m off, within the bound).
    // With submap parts (session 64) the scans before it are placed otherwise and ICP there no
    // longer needs refusing (0.067 m); without them the scan is as it was traced.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/Freiburg79_scan_furnitures.png");
    const test::TempDir dir;
    const std::string log = dir.file("f79.rawlog"), gt = dir.file("f79_gt.txt");
    const auto sim =
        test::runApp("toposlam-sim", "'" + plan + "' --drawn --tour -q -c '" +
                                         test::configIni("sim-office.ini") + "' -o '" + log +
                                         "' --gt '" + gt + "' --people 15 --seed 3");
    ASSERT_EQ(sim.exitCode, 0) << sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(gt);
    for (const bool parts : {true, false}) {
        SCOPED_TRACE(parts ? "submap_parts = true" : "submap_parts = false");
        mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
        ini.write("GraphSlam", "submap_parts", parts);
        const mapping::MappingResult result = mapping::mapLog(log, ini);
        ASSERT_EQ(result.trajectory.size(), truth.size());
        const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
        EXPECT_LT(ate.position.rms, 0.2);
        ASSERT_TRUE(result.statistics);
        if (!parts) {
            EXPECT_GT(result.statistics->icpUnsettledRefused, 0u);
        }
    }
}

TEST(GraphSlam, PeopleCloseByDoNotTurnSettledIcp) {
    // Bormann's office_d toured by B3-sim's "people" robot (15 people walking about), seed 31.
    // At one scan people stood close by, where the submap held them from an earlier keyframe,
    // and ICP, settled on 39 % of the scan, turned the robot 13.7 deg on a straight step of
    // 0.36 m that the odometry read within 0.1 deg: chi-square 174 of the odometry model. The
    // rest of the map kept that turn (ATE 1.15 m). Without the 114 readings of the people ICP
    // keeps the odometry's heading, and the rest of the scan fits that better (84 readings on
    // the submap against 74); it fits too little of the scan to pass, nor does the graph
    // matcher place the scan, so it keeps the odometry (foreground_beyond_odometry): 0.08 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_d_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "people", 31);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    // The gate's lever arm mends part of it on its own too (0.44 m off): left out.
    const FlaggedRun off =
        mapWithFlag(tour.log, truth, "foreground_beyond_odometry", false, {"loop_gate_lever_arm"});
    EXPECT_GT(off.ate, 0.5) << "the tour no longer shows the turn";
    const FlaggedRun on =
        mapWithFlag(tour.log, truth, "foreground_beyond_odometry", true, {"loop_gate_lever_arm"});
    EXPECT_LT(on.ate, 0.2);
}

TEST(GraphSlam, EdgesAmongPeopleTakeTheLoopsCorrection) {
    // Bormann's office_h toured by B3-sim's "people" robot (15 people walking about), seed 34:
    // a 310 m ring of corridors. Where people stood close by, registrations turned the robot
    // by a few degrees, each edge claiming the edge floor's 1 cm and 0.2 deg; back at the start
    // least squares spread the loops' correction evenly along the ring and bent the rest of
    // it (ATE 1.1 m). With the edges of keyframes that see people close by five times as
    // uncertain (foreground_edge_sigma_factor = 5, opt-in for crowded places), the correction
    // goes mostly where they bent the path: 0.11 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_h_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "people", 34);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    const auto ateWithFactor = [&](const char* factor) {
        return mapWithSetting(tour.log, truth, "foreground_edge_sigma_factor", factor).ate;
    };
    EXPECT_GT(ateWithFactor("1"), 0.5) << "the tour no longer shows the bent ring";
    EXPECT_LT(ateWithFactor("5"), 0.2);
}

TEST(GraphSlam, AScanPlacedByOdometryAloneDoesNotPinTheScansThatSeeWhatItSaw) {
    // Bormann's office_a (furnished) toured with a SICK LMS200 (181 readings over 180 deg,
    // 8 m), as B3-sim's "lms200" robot, seed 2. One scan (929 of 1472) neither ICP (a third of
    // it on the submap) nor the graph matcher could place: it kept the odometry's turn, 4.4 deg
    // off. The scans after it saw mostly what it had added to the submap; tied by ICP to the
    // submap's anchor, they claimed its error to a fraction of a degree, and the loops that
    // would have removed it fell outside the gate: trajectory error 1.14 m. Tied to the part of
    // the submap that keyframe starts (submap_parts), the error stays between them and the
    // loops close: 0.090 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_a_furnitures.png");
    const test::TempDir dir;
    const std::string log = dir.file("office_a.rawlog"), gt = dir.file("office_a_gt.txt");
    const auto sim = test::runApp(
        "toposlam-sim", "'" + plan + "' --drawn --tour -q -c '" +
                            test::configIni("sim-office.ini") + "' -o '" + log + "' --gt '" + gt +
                            "' --beams 181 --fov-deg 180 --max-range 8 --seed 2");
    ASSERT_EQ(sim.exitCode, 0) << sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(gt);
    const mapping::MappingResult result =
        mapping::mapLog(log, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    ASSERT_EQ(result.trajectory.size(), truth.size());
    const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
    EXPECT_LT(ate.position.rms, 0.2);
    ASSERT_TRUE(result.statistics);
    EXPECT_GT(result.statistics->tiedToLaterPart, 0u);
}

TEST(GraphSlam, PeopleWalkingAlongDoNotTakeBackTheRobotsStep) {
    // A generated ring building (B4-rings' ring03) toured with 15 people walking about, as
    // B3-sim's "people" robot, seed 2. Along its corridors people walk with the robot; where
    // they hide enough of the walls, ICP from the odometry (which has the step right) ends
    // with too little of the scan on the submap, and the graph matcher, fitted to the people
    // the last keyframe saw one step back, takes back the robot's step: two scans 0.30 and
    // 0.28 m off their true step along the corridor. Without the people (the scan's foreground
    // objects) the rest of the scan fits no better there than where ICP ended, so the answer
    // is refused and the scan keeps the odometry (matcher_foreground_check).
    const test::TempDir dir;
    const GeneratedTour tour =
        tourGeneratedBuilding(dir, 3, simulation::BuildingStyle::Ring,
                              test::configIni("sim-office.ini"), " --people 15 --seed 2");
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    // Every scan's step from the scan before it (consecutive relations only).
    evaluation::GroundTruthRelationOptions stepsOnly;
    stepsOnly.baseSeparation = 0;
    const evaluation::PoseRelations steps = evaluation::relationsFromGroundTruth(truth, stepsOnly);
    for (const bool check : {true, false}) {
        SCOPED_TRACE(check ? "matcher_foreground_check = true"
                           : "matcher_foreground_check = false");
        mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
        ini.write("GraphSlam", "matcher_foreground_check", check);
        const mapping::MappingResult result = mapping::mapLog(tour.log, ini);
        ASSERT_EQ(result.trajectory.size(), truth.size());
        ASSERT_TRUE(result.statistics);
        const auto stepErrors = evaluation::evaluateRelativePoseError(result.trajectory, steps);
        ASSERT_EQ(stepErrors.matchedRelations, truth.size() - 1);
        const double worstStep = stepErrors.translation.max;  // m
        if (check) {
            EXPECT_GT(result.statistics->matcherRefusedForeground, 0u);
            EXPECT_LT(worstStep, 0.25);
            EXPECT_LT(
                evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth).position.rms,
                0.25);
        } else {
            EXPECT_EQ(result.statistics->matcherRefusedForeground, 0u);
            EXPECT_GT(worstStep, 0.25) << "the scenario no longer has the matcher fooled";
        }
    }
}

TEST(GraphSlam, PlacesLaterKeyframesSawThroughDoNotHoldTheScan) {
    // Generated building 51 (B4-gen's gen51) toured with 15 people walking about, as B3-sim's
    // "people" robot, seed 2. The places where people stood when a keyframe saw them stay in
    // the submap; ICP's first stage fitted to them pulled scans off, and the tour mapped at an
    // ATE of 0.091 m. Where a later keyframe's beams passed through such a place, it no longer
    // holds a scan (free_space_carving): 0.015 m.
    const test::TempDir dir;
    const GeneratedTour tour =
        tourGeneratedBuilding(dir, 51, simulation::BuildingStyle::Office,
                              test::configIni("sim-office.ini"), " --people 15 --seed 2");
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    expectSettingMends(tour, "free_space_carving", 0.04, 0.06,
                       "the scenario no longer has ICP held by where people stood");
}

TEST(GraphSlam, ASlideThatSeesThroughTheSubmapIsHeldAtTheOdometry) {
    // Generated ring building 51 (B4-rings' ring51) toured by B3-sim's poor-odometry robot,
    // seed 4. Turning out of a corridor from an odometry heading 6 deg short of the turn, ICP
    // slid 0.33 m along the heading to where 282 of the scan's 354 readings lay on the submap,
    // 50 more than at the odometry's position, so the fit did not hold it (along_heading_margin)
    // and the tour followed it: ATE 0.134 m, that step 0.37 m off. At ICP's pose the scan saw
    // through 53 submap points, at the odometry's 4: held there (along_heading_free_space),
    // the step is within 4 cm of the truth and the ATE 0.017 m.
    const test::TempDir dir;
    const GeneratedTour tour =
        tourByBenchRobot(dir, 51, simulation::BuildingStyle::Ring, "poor-odometry", 4);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    expectSettingMends(tour, "along_heading_free_space", "0.1", "0", 0.04, 0.08,
                       "the scenario no longer has a slide the fit lets pass");
}

TEST(GraphSlam, StallsInTheBendsOfARingBuildingLoseNoCorridor) {
    // Generated ring building 51 (B4-rings' ring51) toured by B3-sim's stalling robot.
    // - Seed 2: in a bend the odometry stalls twice; each catch-up is predicted by the last
    //   registered motion, which ICP, entering a corridor, left short. The readings after, in
    //   step again (0.35 m a scan), looked far longer than that short motion and were taken for
    //   more catching up, each predicted shorter still: five scans, 1.2 m of corridor lost, ATE
    //   0.38 m. A catch-up now ends once it has delivered the stall's motion: 0.048 m.
    // - Seed 3: the robot stops turning during a stall. ICP from the last motion (14 deg where
    //   the robot turned 2) ends 12 deg off on a third of the scan and fails, and the scan kept
    //   the last motion's turn: ATE 0.38 m (0.014 m before the catch-up rule, by chance: the
    //   scans before it a millimetre elsewhere). ICP from the standstill, which passes and fits
    //   more of the scan, is now taken: 0.014 m.
    for (const int seed : {2, 3}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const test::TempDir dir;
        const GeneratedTour tour =
            tourByBenchRobot(dir, 51, simulation::BuildingStyle::Ring, "stalling-odometry", seed);
        ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
        const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
        const mapping::MappingResult result = mapping::mapLog(
            tour.log, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
        ASSERT_EQ(result.trajectory.size(), truth.size());
        ASSERT_TRUE(result.statistics);
        EXPECT_GT(result.statistics->odometryCatchUps, 0u) << "the odometry must catch up";
        // A tenth of the 1.2 m lost before, and far under the 0.38 m either failure gave.
        EXPECT_LT(
            evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth).position.rms,
            0.1);
    }
}

TEST(GraphSlam, ACatchUpAfterShortReadingsAtAThirdOfTheScanRateIsBridged) {
    // Bormann's lab_c toured by B3-sim's stalling robot, seed 3, one scan in three kept (1 m
    // between scans). Its stalls fall within scan intervals: at t = 88 and 91 s the odometry
    // read 0.68 m where registration saw the robot go 1.02 m, and the next reading held the
    // 0.68 m missed on top of its own step (1.48 m and 52 deg where the robot went 0.79 m and
    // turned 43). Taken for a jump, the step was predicted by the last motion (33 deg off); ICP
    // settled 0.36 m off, and the map with it (ATE 0.47 m). Less the shortfall the reading is
    // the step: 0.009 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_c_scan_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "stalling-odometry", 3);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const mapping::MappingResult result =
        mapping::mapLog(thirdOfTheScans(dir, tour),
                        mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    ASSERT_TRUE(result.statistics);
    EXPECT_GT(result.statistics->odometryShortfallsBridged, 0u) << "the readings must fall short";
    const auto ate = evaluation::evaluateAbsoluteTrajectoryError(
        result.trajectory, io::loadTrajectory(tour.groundTruth));
    EXPECT_EQ(ate.matchedPoses, result.trajectory.size());
    // The laser's noise (1 cm) and a third of the scans: a few centimetres, a tenth of before.
    EXPECT_LT(ate.position.rms, 0.05);
}

TEST(GraphSlam, AReadingInStepWithTheOneBeforeIsNoJump) {
    // Bormann's office_i toured by B3-sim's stalling robot, seed 8, one scan in three kept
    // (0.9 m between scans). Along a bare corridor the odometry read 0.30 m, registration had
    // nothing to say otherwise, and the next reading held the rest (1.49 m): a jump, and the
    // graph matcher placed the scan 0.2 m on. From then on every reading, 0.9 m like the one
    // before, departed from that short registered motion by more than the jump bounds, was
    // taken for a jump, and the matcher held the robot where it was for nine scans, 8 m of
    // corridor lost (ATE 8.9 m). A reading in step with the one before is no jump.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_i_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "stalling-odometry", 8);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const std::string third = thirdOfTheScans(dir, tour);
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    // Taking the catch-up as read where the scan cannot tell it from the last motion
    // (undecided_jump_by_prior) mends the tour on its own (0.33 m with both rules): it is left
    // out to test this one.
    const auto ate = [&](bool on) {
        return mapWithFlag(third, truth, "jump_only_out_of_step", on, {"undecided_jump_by_prior"})
            .ate;
    };
    const double ateOff = ate(false);
    EXPECT_GT(ateOff, 5.0) << "the scenario no longer shows the corridor lost";
    // Under a third of it (2.0 m). What is left: three short readings along corridors whose
    // scans registration places 0.6 m short, and the catch-up after each, 0.7 m short.
    EXPECT_LT(ate(true), ateOff / 3);
}

TEST(GraphSlam, AJumpAfterAReadingThatMissedTheStepIsReadWithIt) {
    // Generated building 60 toured by B3-sim's stalling robot, seed 1, one scan in three kept.
    // At the end of a turn the odometry stalls within a scan interval: it reads no distance and
    // 15 deg of turn where the robot went 0.45 m and turned 33, and ICP, started there, places
    // the scan 0.33 m short (with the turn right). The next reading, 1.54 m and 12 deg, holds
    // the rest on top of a step of 1.05 m straight on: a jump. Applied where registration
    // placed the scan before, whose heading is the robot's and not the odometry's, the reading
    // is 14 deg off; the last motion, a turn of 33 deg, is farther off still. Both failed, the
    // scan kept the last motion, and the rest of the tour followed it 35 deg off (ATE 3.9 m).
    // The two readings together are the robot's motion over both scans: ICP from there.
    // On, a tenth of the failure's error. (What is left, 0.09 m, is stalls along corridors
    // whose scans registration places short: loops into them do not fit the graph.) Since
    // session 92 the catch-up's ICP passes by the turn of its chord too (jump_sideways_by_turn,
    // off here: with it the tour maps at 0.07 m either way).
    expectRuleMendsGen60AtAThird("jump_over_two_readings",
                                 &mapping::SlamStatistics::odometryJumpsOverTwoReadings, 0.4, 1.0,
                                 {"jump_sideways_by_turn"});
}

TEST(GraphSlam, ACatchUpTheScanCannotTellFromTheLastMotionIsTakenAsRead) {
    // Generated building 60 toured by B3-sim's stalling robot, seed 1, one scan in three kept.
    // Along a corridor the odometry reads 0.3 m of a 0.95 m step, and registration, which
    // nothing along the corridor corrects, follows it; the next reading catches up and is a
    // jump. ICP from that reading and ICP from the last motion both pass and both hold where
    // they start: the scan cannot tell them apart. The graph matcher was asked next, and its
    // answer, confirmed on the same submap, put the robot near where the short reading had
    // left it: the catch-up was lost (ATE 0.23 m). Most of this log's clear jumps were the
    // odometry's own steps (fast turns), so the catch-up is taken as read.
    // Measured 0.094 m on, 0.228 m off (jump_sideways_by_turn off in both, as before session
    // 92: it changes which catch-ups reach the prior).
    expectRuleMendsGen60AtAThird("undecided_jump_by_prior",
                                 &mapping::SlamStatistics::odometryJumpsByPrior, 0.15, 0.18,
                                 {"jump_sideways_by_turn"});
}

TEST(GraphSlam, TheMatcherPlacesACatchUpAgainstAKeyframeRegistrationPlaced) {
    // Bormann's lab_f toured by B3-sim's stalling robot, seed 5, one scan in three kept. The
    // odometry stalls whole (reads nothing) while the robot turns 17 deg and goes 1 m; the last
    // motion, a 55 deg turn, and the standstill are both outside ICP's basin, so the scan keeps
    // the last motion, 38 deg off, and becomes a keyframe placed by odometry alone. The next
    // reading catches up, a jump, and the graph matcher placed that scan right relative to that
    // keyframe, so the rest of the tour kept its 38 deg (ATE 2.0 m). Matched against the keyframe
    // a registration placed before it, the catch-up lands where the robot is. (Not making
    // that scan a keyframe at all, defer_keyframe_in_stall, mends the tour too, 0.66 m, and
    // bridging the stall nothing placed, bridge_unplaced_stalls, further, 0.15 m: both are
    // left out to test this rule.)
    // Measured 0.37 m on: what is left is the stalls along corridors (0.3-0.6 m short steps).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_f_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(
        plan, 5, "matcher_from_registered_keyframe",
        &mapping::SlamStatistics::graphMatcherFromRegisteredKeyframe, 1.5, 3,
        "the scenario no longer shows the heading kept",
        {"defer_keyframe_in_stall", "bridge_unplaced_stalls"});
}

TEST(GraphSlam, AStalledScanNothingPlacedIsNoKeyframe) {
    // Bormann's office_h toured by B3-sim's stalling robot, seed 6, one scan in three kept.
    // The odometry stalls whole (reads nothing) while the robot goes 0.94 m and turns 20 deg
    // right; the scan keeps the last motion, 8 deg left, since nothing registers it, and
    // becomes a keyframe 28 deg off. The catch-up after it is bridged and ICP places it right,
    // but that keyframe's readings stay in the submap 28 deg off, and the next steps, partly
    // registered on them, came out 7 and 8 deg off (ATE 1.2 m). Not a keyframe, the scan
    // leaves the submap and the matcher's reference alone. (short_turn_second_opinion mends
    // this tour on its own too, 0.08 m, and so do bridge_stall_and_step, 0.08 m, and the
    // gate's lever arm, 0.10 m, closing the loops past the error: all three are left out to
    // test this rule.) Measured 0.09 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_h_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(
        plan, 6, "defer_keyframe_in_stall", &mapping::SlamStatistics::keyframesDeferredInStall, 0.8,
        5, "the scenario no longer shows the keyframe's error kept",
        {"short_turn_second_opinion", "bridge_stall_and_step", "loop_gate_lever_arm"});
}

TEST(GraphSlam, AScanNothingPlacedIsTriedWithoutTheTurnShortReadingsMissed) {
    // Bormann's lab_f toured by B3-sim's stalling robot, seed 7, one scan in three kept. A
    // short reading misses 24 deg of a turn, the graph matcher places that scan, and the next
    // reading, as long as the robot's step, delivers the missed turn: 25 deg read where the
    // robot went straight on. ICP from 24 deg off failed, so did the matcher, and the scan
    // kept the reading; the rest of the tour kept its heading (ATE 1.6 m).
    // Measured 0.14 m on. (turned_start_search mends this tour on its own too, 0.065 m, from
    // the reading turned farther, and so does the gate's lever arm, 0.14 m, closing the loops
    // past the error: both are left out to test this rule.)
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_f_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 7, "missed_turn_start",
                                        &mapping::SlamStatistics::icpPastMissedTurn, 1.0, 5,
                                        "the scenario no longer shows the heading kept",
                                        {"turned_start_search", "loop_gate_lever_arm"});
}

TEST(GraphSlam, AHeadingThatStalledThroughTheIntervalIsFoundFromFartherTurnedStarts) {
    // Bormann's lab_f toured by B3-sim's stalling robot, seed 14, one scan in three kept. In a
    // turn the odometry reads 0.72 m and 16 deg where the robot went 0.68 m and turned 52: ICP
    // from the reading, 36 deg off, fails (0.31 of the scan on the submap), and so do the
    // graph matcher and every other start; the scan kept the reading, and the rest of the
    // tour kept its heading (ATE 7.4 m). From the reading turned by 17, 26 and 34 deg ICP
    // settles on the same pose, 36 deg on, 0.24 m aside (the chord of the turn).
    // Measured 0.40 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_f_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 14, "turned_start_search",
                                        &mapping::SlamStatistics::icpFromTurnedStarts, 5.0, 5,
                                        "the scenario no longer shows the heading kept");
}

TEST(GraphSlam, IcpShortOfATurnOnLittleOfTheScanIsTriedFromTheLastMotion) {
    // Bormann's lab_b toured by B3-sim's stalling robot, seed 8, one scan in three kept.
    // Mid-turn (47 deg a step) a short reading (0.35 m, -12 deg, where the robot went 0.90 m
    // and turned -47 deg) starts ICP 35 deg short of the turn; it ends at -15 deg with 0.37
    // of the scan on the submap, not settled, the second opinion's turned starts (+-17 deg)
    // do not reach, and the rest of the tour keeps the 32 deg (ATE 3.0 m). From the last
    // motion ICP puts 220 of the 361 readings on the submap where the short start put 67,
    // and that start is taken. (second_opinion_wide_turns mends this tour on its own too,
    // 0.007 m, from the reading turned by 34 deg, and so does bridge_stall_and_step, 0.011 m:
    // both are left out to test this rule.) Measured 0.007 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_b_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 8, "short_turn_second_opinion",
                                        &mapping::SlamStatistics::icpShortOfTurnReplaced, 2.0, 20,
                                        "the scenario no longer shows the heading kept",
                                        {"second_opinion_wide_turns", "bridge_stall_and_step"});
}

TEST(GraphSlam, AReadingThatMissedATurnTheOtherWayIsTriedFromFartherTurnedStarts) {
    // Bormann's office_f toured by B3-sim's stalling robot, seed 10, one scan in three kept (a
    // seed no other rule was traced on). After a step that turned 53 deg right, a short reading
    // (0.35 m, -13 deg) misses the robot's step of 0.94 m and +18 deg. ICP from it ends 32 deg
    // off on 87 readings, unsettled; the last motion's start turns the wrong way, the turned
    // starts (+-17 deg at most) do not reach, the matcher does not answer, and the rest of the
    // tour keeps the 32 deg (ATE 8.5 m). From the prediction turned by 26 deg (and by 34) ICP
    // settles right, on 189 readings.
    // Measured 0.21 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_f_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 10, "second_opinion_wide_turns",
                                        &mapping::SlamStatistics::icpWideTurnStarts, 5.0, 10,
                                        "the scenario no longer shows the heading kept");
}

TEST(GraphSlam, ASecondOpinionIsRefutedWhereAStartBeyondAJumpFitsClearlyBetter) {
    // Bormann's Freiburg79 toured by B3-sim's stalling robot, seed 9, one scan in three kept.
    // After three turns on the spot (48 deg each) a short reading (0.35 m, 15 deg) misses the
    // robot's 0.92 m and 43 deg. ICP from it ends 24 deg off on 59 readings, unsettled; the
    // second opinion's start from the last motion (the turn on the spot) ends right, on 341
    // readings, but 0.9 m from that start, beyond the jump bounds, and was dropped: the answer
    // stayed, and the rest of the tour kept the 24 deg (ATE 1.9 m). Refuted, the answer gives
    // way to the graph matcher, which places the scan right.
    // Measured 0.03 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/Freiburg79_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 9, "second_opinion_refuted_beyond_jump",
                                        &mapping::SlamStatistics::icpRefutedBeyondJump, 1.0, 10,
                                        "the scenario no longer shows the heading kept");
}

TEST(GraphSlam, TheWiderTurnedStartsVouchForNoAnswerAStartBeyondAJumpRefutes) {
    // Bormann's NLB toured by B3-sim's stalling robot, seed 12, one scan in three kept. The
    // odometry stalls while the robot turns 48 deg on the spot. ICP from the standstill ends
    // on 65 of 361 readings, unsettled; from the graph matcher's answer it ends 90 deg off the
    // turn, on 256, beyond the odometry's noise where no start settled: refused so far. The
    // wider ring (second_opinion_wide_turns) has one start settle there, which vouched for
    // that answer (ATE 8.4 m), and two end on the turn itself, on 356 readings, but 48 deg
    // from the standstill, beyond the jump bounds. Those refute the answer.
    // Measured 0.04 m on.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/NLB_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 12, "second_opinion_refuted_beyond_jump",
                                        &mapping::SlamStatistics::icpRefutedBeyondJump, 5.0, 20,
                                        "the scenario no longer shows the wrong turn vouched for");
}

TEST(GraphSlam, AStartThatFitsOnlyWhatAnOdometryPlacedKeyframeAddedRefutesNothing) {
    // Bormann's office_i toured by B3-sim's stalling robot, seed 10, one scan in three kept. A
    // short reading (0.34 m, +3 deg, where the robot went 1.05 m and turned -13 deg) places
    // nothing: its keyframe keeps the reading, 16 deg off, and starts a part of the submap. At
    // the catch-up after it ICP's answer lies within a degree of the prediction, on 118 of 361
    // readings, and a start 26 deg off ends 17 deg off on 327: on the copy of the place that
    // keyframe added, turned with it. That end refuted the answer, the graph matcher placed the
    // scan on the keyframe's error, and the rest of the tour kept the 16 deg (ATE 2.84 m). The
    // refutation now weighs fits on the submap before its newest part only.
    // Measured 0.11 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_i_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "stalling-odometry", 10);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const std::string third = thirdOfTheScans(dir, tour);
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    const FlaggedRun run = mapWithFlag(third, truth, "second_opinion_refuted_beyond_jump", true);
    EXPECT_GT(run.statistics.registrationFailed, 0u)
        << "the scenario no longer has a keyframe placed by odometry alone";
    EXPECT_LT(run.ate, 0.5);
}

TEST(GraphSlam, ATurnedStartThatFitsClearlyMoreReplacesTheMatchersAnswer) {
    // Bormann's office_c toured by B3-sim's stalling robot, seed 9, one scan in three kept. A
    // turn on the spot of 48 deg is read as 66: ICP from the reading ends 7 deg from it, still
    // 11 deg off the turn, and is refused for the size of its correction, and the graph
    // matcher answers 12 deg off the other way, 0.44 m from where the robot stood. From the
    // reading turned 17 deg back ICP settles right, on clearly more of the scan, and replaces
    // the answer (ATE 1.26 -> 0.17 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_c_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 9, "matcher_second_opinion",
                                        &mapping::SlamStatistics::icpOutfittedMatcher, 0.8, 5,
                                        "the scenario no longer shows the matcher's turned answer");
}

TEST(GraphSlam, AMatcherAnswerWithinTheCatchUpAfterAStallIsNoJump) {
    // Bormann's lab_b toured by B3-sim's stalling robot, seed 12, one scan in three kept. The
    // odometry stalls for a scan in which the robot goes 1.04 m (the matcher places it), then
    // reads 1.19 m and 17 deg: the stall's motion and the scan's own, 0.16 m and a 47 deg turn
    // on the spot. No longer than the last motion, that reading is no catch-up to the stall
    // rules; ICP from it fails, and the matcher's right answer, 1.04 m from it, was refused as a
    // look-alike, the odometry kept (ATE 1.17 m). Within the jump bounds of the reading less the
    // motion registered over the stall it is no jump (0.07 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_b_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(
        plan, 12, "matcher_bounded_by_catch_up",
        &mapping::SlamStatistics::graphMatcherWithinStallCatchUp, 0.8, 5,
        "the scenario no longer shows the catch-up that read no more than the last motion");
}

TEST(GraphSlam, ACatchUpWhoseHeadingLaggedTooMayEndAsideByTheTurnOfItsChord) {
    // Bormann's lab_d toured by B3-sim's stalling robot, seed 10, one scan in three kept. A
    // short reading (0.33 m, -5 deg, where the robot went 1.04 m and turned -17 deg) is placed
    // at its distance along a corridor; the next reading catches up, 1.76 m and -13 deg where
    // the robot went straight on. ICP from it finds the robot's heading (+14 deg) 0.36 m aside,
    // beyond the 0.21 m a step of 1.76 m may correct sideways, and the graph matcher's
    // look-alike 0.06 m behind the short scan was taken: the tour lost 1.7 m (ATE 0.69 m). The
    // reading held the 12 deg the short one missed, and a heading that lagged through the step
    // turns its chord by about half the lag: 1.76 m x sin 6 deg = 0.19 m more, 0.40 m in all,
    // and the catch-up is taken (0.08 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_d_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(
        plan, 10, "jump_sideways_by_turn", &mapping::SlamStatistics::odometryJumpsSidewaysByTurn,
        0.4, 4, "the scenario no longer shows the catch-up refused for its sideways correction");
}

TEST(GraphSlam, TheFirstTurnsOnTheSpotGetTheSecondOpinionToo) {
    // office_c's tour two tests above (stalling robot, seed 9, one scan in three): at its 20th
    // scan the robot turns 45 deg on the spot, the odometry reads 30, and ICP from there ends
    // 15 deg short, unconverged, on a fifth of the scan. The second
    // opinion judges "unsettled" against the median residual of the registrations so far,
    // which it took only from the twentieth on: the log's first turns went unchecked. From the
    // fifth on, every step of the tour's first 40 scans is right to a degree.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_c_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "stalling-odometry", 9);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    mrpt::config::CConfigFileMemory ini(test::readFile(test::configIni("toposlam-slam.ini")));
    const mapping::MappingResult result = mapping::mapLog(thirdOfTheScans(dir, tour), ini);
    ASSERT_GE(result.trajectory.size(), 40u);
    const auto truthAt = [&](double stamp) {
        const auto it = std::find_if(truth.begin(), truth.end(), [&](const io::TimedPose2D& p) {
            return std::abs(p.stamp - stamp) < 1e-3;
        });
        EXPECT_NE(it, truth.end());
        return it == truth.end() ? mrpt::poses::CPose2D() : mrpt::poses::CPose2D(it->pose);
    };
    double worstDeg = 0;
    for (std::size_t i = 1; i < 40; ++i) {
        const auto& a = result.trajectory[i - 1];
        const auto& b = result.trajectory[i];
        const double estimated =
            (mrpt::poses::CPose2D(b.pose) - mrpt::poses::CPose2D(a.pose)).phi();
        const double real = (truthAt(b.stamp) - truthAt(a.stamp)).phi();
        worstDeg =
            std::max(worstDeg, std::abs(mrpt::RAD2DEG(mrpt::math::wrapToPi(estimated - real))));
    }
    EXPECT_LT(worstDeg, 1.0);
}

TEST(GraphSlam, AStallNothingPlacedIsBridgedWhateverTurnTheLastMotionCarriedOn) {
    // Bormann's lab_f toured by B3-sim's stalling robot, seed 5, one scan in three kept. In a
    // bend the odometry stalls for one scan: neither ICP nor the graph matcher places it, and it
    // keeps the last motion, 0.62 m and 55 deg, where the robot went 1.05 m and turned 17 deg.
    // The reading after holds both scans' motion (2.0 m, 20 deg). Taken as a reading that turned
    // otherwise than registration saw, it was refused as a jump, the graph matcher placed the
    // scan 1.2 m short, and the rest of the tour kept it (ATE 0.66 m). Nothing saw the 55 deg:
    // the reading less that guess is the step, and the stalled scan goes between (0.15 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_f_scan_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 5, "bridge_unplaced_stalls",
                                        &mapping::SlamStatistics::odometryUnplacedStallsBridged,
                                        0.5, 3, "the scenario no longer shows the stall refused");
}

TEST(GraphSlam, AStallsTurnTheReadingAfterRefutesIsBridgedAsOneNothingPlaced) {
    // Bormann's lab_intel toured by B3-sim's stalling robot, seed 14, one scan in three kept.
    // The odometry stalls for one scan where the robot went 0.52 m and turned +30 deg; from
    // the standstill and from the last motion (-33 deg) ICP settles nowhere, and the graph
    // matcher places the scan at -60 deg: a look-alike of the room turned by 90 deg that fits
    // 91 % of the scan. As a keyframe it went into the submap, the next scan registered on
    // it, 90 deg off too, although the reading over both scans turned +83 deg; two stalls
    // later the tour was turned by 180 deg (ATE 16 m). A reading that turns otherwise than
    // the stall's scans were registered by more than the jump bound of the two intervals it
    // spans (143 deg here, beyond 90) refutes the matcher: the stall is bridged as one nothing
    // placed, the scan after it predicted by the reading from the scan before the stall
    // (0.10 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_intel_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 14, "bridge_refuted_stalls",
                                        &mapping::SlamStatistics::odometryRefutedStallsBridged, 5.0,
                                        20, "the scenario no longer shows the turned look-alike");
}

TEST(GraphSlam, ACatchUpAfterAStallTheRobotStoppedInStartsFromTheReadingLessTheStall) {
    // Bormann's office_b toured by B3-sim's stalling robot, seed 14, one scan in three kept.
    // The graph matcher places a stall's scan right (1.04 m, -18 deg); then the robot stops
    // and turns on the spot (0.04 m, -47 deg), and the reading after the stall holds both,
    // 1.09 m and -63 deg: a catch-up, predicted by the last motion. ICP from it, and from the
    // reading, settles nowhere, and the scan kept the last motion, 1 m and 28 deg off (ATE
    // 4.4 m). The reading less the stall's registered step is the robot's (2.5 m: the tour's
    // other faults stay).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_b_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 14, "catch_up_less_stall",
                                        &mapping::SlamStatistics::odometryCatchUpsLessStall, 4.0,
                                        1.5, "the scenario no longer shows the catch-up unplaced");
}

TEST(GraphSlam, ACatchUpAsLongAsTheRegisteredStallPlusAStepIsBridgedWhateverItTurned) {
    // Bormann's office_a toured by B3-sim's stalling robot, seed 41, at every scan. After a
    // stall registration followed (1.05 m, -11 deg) the reading holds it and its own interval,
    // where the robot turned +19 deg: 1.39 m = 1.05 + 0.34. Turned otherwise than registration
    // saw, it was taken for a catch-up and predicted by the last motion; ICP from there settled
    // 0.8 m on (ATE 0.31 m). The lengths add up: the reading less the registered stall is the
    // step (0.02 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_a_furnitures.png");
    expectRuleMendsStallingPlan(plan, 41, /*atAThird=*/false, "bridge_stall_and_step",
                                &mapping::SlamStatistics::odometryStallsAndStepBridged, 0.2, 5,
                                "the tour no longer shows the catch-up ICP settled past");
}

TEST(GraphSlam, ATurnOnTheSpotTheOdometryReadShortGetsASecondOpinion) {
    // Bormann's office_e toured by B3-sim's stalling robot, seed 8, one scan in three kept. The
    // robot stops after a 1.06 m step and turns -48 deg on the spot; the odometry reads -16.
    // ICP from the reading settles 30 deg short on 39 % of the scan, nothing along the heading
    // says otherwise, and the rest of the tour kept the turn (ATE 3.3 m). A turn on the spot
    // fitted so poorly gets the second opinion, and ICP from a start turned farther settles
    // right on 69 % of the scan (0.02 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_e_furnitures.png");
    expectRuleMendsStallingPlanAtAThird(plan, 8, "spot_turn_second_opinion",
                                        &mapping::SlamStatistics::icpShortOnTheSpotReplaced, 1.0,
                                        10, "the scenario no longer shows the turn settled short");
}

TEST(GraphSlam, AStallsStepTheScanBoreOutFromBothStartsIsNotTakenBack) {
    // The mirror image of generated building 51 toured by the stalling robot (B3, "The logs'
    // mirror images"). At a stall along a corridor ICP from the standstill and from the last
    // motion end at the same pose, 0.35 m on, nearer the last motion: the scan bears the step
    // out. A piece of furniture beside the robot is a foreground object, and measured from the
    // standstill the step looked like a correction it had pushed ICP into (foreground_check):
    // without it ICP stayed at the standstill, the step was taken back and the rest of the
    // tour was 0.35 m off (ATE 0.079 m, one step 0.36 m off). The checks now measure the
    // correction from the last motion there: ATE 0.005 m.
    const test::TempDir dir;
    const std::string simIni = dir.file("stalling.ini");
    evaluation::writeIniWithSettings(
        test::configIni("sim-office.ini"), simIni,
        {{"Odometry", "stall_probability", "0.05"}, {"Odometry", "stall_max_scans", "3"}});
    const GeneratedTour tour =
        tourGeneratedBuilding(dir, 51, simulation::BuildingStyle::Office, simIni, " --seed 1");
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    io::LogConversionOptions mirror;
    mirror.rawlogPath = dir.file("mirrored.rawlog");
    mirror.alteration.mirror = true;
    io::convertLaserLog(tour.log, mirror);
    const io::Trajectory2D truth = io::mirroredTrajectory(io::loadTrajectory(tour.groundTruth));

    const mapping::MappingResult result = mapping::mapLog(
        mirror.rawlogPath, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    ASSERT_EQ(result.trajectory.size(), truth.size());
    ASSERT_TRUE(result.statistics);
    EXPECT_GT(result.statistics->odometryStallsBridged, 10u) << "the odometry must stall";
    evaluation::GroundTruthRelationOptions stepsOnly;
    stepsOnly.baseSeparation = 0;
    const auto steps = evaluation::evaluateRelativePoseError(
        result.trajectory, evaluation::relationsFromGroundTruth(truth, stepsOnly));
    // 1 cm range noise, 0.35 m steps: every step to centimetres (measured 0.025 m at worst).
    EXPECT_LT(steps.translation.max, 0.1);
    EXPECT_LT(evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth).position.rms,
              0.03);
}

TEST(GraphSlam, AStallOfTheWheelsWhileTheHeadingReadsIsPredictedByTheLastMotion) {
    // mit-csail's odometry reads 0.004, 0 and 0 m at three scans where the robot went 0.21 m
    // in each 0.21 s, its turn read all along, then 0.834 m. Along a corridor ICP keeps the
    // standstill it is started from: the three scans stayed 0.3 m behind, and the catch-up
    // read like a jump. The simulator's stalls with the heading still reading, at mit-csail's
    // speed and scan spacing (1 m/s, a scan every 0.2 m): a robot cannot slow from 1 m/s to
    // nothing within 0.2 s, so such a reading is a stall (OdometryLag::translationStalled)
    // and is predicted by the last motion, as a reading of exactly zero is.
    const test::TempDir dir;
    const std::string simIni = dir.file("stalling.ini");
    evaluation::writeIniWithSettings(test::configIni("sim-office.ini"), simIni,
                                     {{"Odometry", "stall_probability", "0.05"},
                                      {"Odometry", "stall_max_scans", "3"},
                                      {"Odometry", "stall_heading_reads", "true"},
                                      {"Tour", "max_speed", "1.0"},
                                      {"Tour", "scan_distance", "0.2"}});
    const GeneratedTour tour =
        tourGeneratedBuilding(dir, 51, simulation::BuildingStyle::Office, simIni, " --seed 1");
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    expectSettingMends(tour, "predict_stalls_by_last_motion", 0.04, 0.1,
                       "the scenario no longer needs the stalls predicted");
}

TEST(GraphSlam, AShortLaserRoundARingBuildingClosesTheLoopBackToTheStart) {
    // A generated ring building (B4-rings' ring06, a 590 m tour) toured with a TurtleBot3's
    // LDS-01 (360 readings all round, 3.5 m, 3 cm noise), as end to end in B4 ("Rooms on a
    // short laser's grids"). Along its 2 m corridors the short laser's heading drifts; back at
    // the start the graph has the robot 2.2 m off, while the gate, adding heading variance only
    // over the 0.4-1.7 m between the two keyframes, allowed 0.5 m: the loops were refused and
    // the map stayed 2 m apart (trajectory error 0.61 m). Each edge's heading variance taken
    // with its lever arm along the chain (loop_gate_lever_arm) lets them in.
    const test::TempDir dir;
    std::string ini = test::readFile(test::configIni("sim-office.ini"));
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"beams = 361", "beams = 360"},
             {"fov_deg = 270", "fov_deg = 359"},
             {"max_range = 20", "max_range = 3.5"},
             {"range_noise = 0.01", "range_noise = 0.03"},
             {"look_into_unseen = false", "look_into_unseen = true"}}) {
        const std::size_t at = ini.find("\n" + from + "\n");
        ASSERT_NE(at, std::string::npos) << from;
        ini.replace(at + 1, from.size(), to);
    }
    const std::string simIni = dir.file("lds01.ini");
    std::ofstream(simIni) << ini;
    const GeneratedTour tour =
        tourGeneratedBuilding(dir, 6, simulation::BuildingStyle::Ring, simIni);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    expectSettingMends(tour, "loop_gate_lever_arm", 0.25, 0.4,
                       "the scenario no longer needs the lever arm");
}

TEST(GraphSlam, AmongPeopleTheLeverArmClosesTheLoopBackRoundTheBuilding) {
    // Bormann's lab_a toured by B3-sim's "people" robot (15 people walking about), seed 32.
    // Steps a few degrees off where people stood close add up along the tour; back where it
    // had been, the loops are metres and degrees off the graph, beyond the gate. The path's
    // covariance with each heading error swung by its lever arm explains them (a turn, and the
    // shift it makes across the chain): 0.52 m without, 0.30 m with.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_a_scan_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "people", 32);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    expectSettingMends(tour, "loop_gate_lever_arm", 0.4, 0.45,
                       "the tour no longer needs the lever arm");
}

TEST(GraphSlam, ALookAlikeShiftWithoutTheTurnIsNotLetInByTheLeverArm) {
    // Bormann's lab_f toured by B3-sim's "people" robot, seed 32. Two matches, 1300 keyframes
    // apart, put the robot 3.3 m along a corridor from where it was, turned 0.8 deg (a
    // look-alike stretch). The path's swung covariance alone would let them in (chi-square 11
    // of 16.27: over a chain that long, heading errors that cancel explain a shift), and the
    // tour broke, 0.09 -> 1.06 m. A heading error explains a shift only as long as its turn
    // times the farthest the chain went from the robot (LoopCloser::swungByTurn), and 0.8 deg
    // would need a lever of 230 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/lab_f_scan_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "people", 32);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    const mapping::MappingResult result =
        mapping::mapLog(tour.log, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    ASSERT_EQ(result.trajectory.size(), truth.size());
    EXPECT_LT(evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth).position.rms,
              0.2);
}

TEST(GraphSlam, ANarrowLaserIsReportedAsAWeakFrontEnd) {
    // The office toured with a depth camera's scan (58 deg, 320 readings, 4.5 m): ICP finds too
    // little wall in view for about a third of the scans, and the map comes out worse than the
    // odometry (benchmarks.md, B3). The summary says so; with the simulator's default laser
    // (270 deg, 20 m) it does not.
    const auto mapWith = [](bool narrowLaser) {
        const test::TempDir dir;
        simulation::SimulatorConfig config;
        if (narrowLaser) {
            config.log.laser.aperture = mrpt::DEG2RAD(58.0);
            config.log.laser.beams = 320;
            config.log.laser.maxRange = 4.5;
        }
        config.log.seed = 3;
        return mapping::mapLog(simulateOfficeTour(config, dir.path()).rawlogPath,
                               mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    };
    const mapping::MappingResult narrow = mapWith(true);
    ASSERT_TRUE(narrow.statistics);
    EXPECT_FALSE(mapping::mostlyUnregistered(narrow));
    EXPECT_TRUE(mapping::weakFrontEnd(narrow));
    EXPECT_NE(mapping::formatSummary(narrow).find("registered by ICP"), std::string::npos);
    EXPECT_TRUE(mapping::summaryJson(narrow).at("weak_front_end").get<bool>());
    const mapping::MappingResult wide = mapWith(false);
    EXPECT_FALSE(mapping::weakFrontEnd(wide));
    EXPECT_EQ(mapping::formatSummary(wide).find("WARNING"), std::string::npos);
    EXPECT_FALSE(mapping::summaryJson(wide).at("weak_front_end").get<bool>());
}

TEST(MappingOutputs, ALoopLeftOpenAtTheEndOfTheLogIsAWarningWithItsStamps) {
    // A loop still awaiting its second match when the log ended, 4.35 m and 10 deg off the
    // graph: the summary warns, names the two scans by their trajectory.txt stamps, and says
    // what it cannot tell (an open map or a look-alike place).
    mapping::MappingResult result;
    result.statistics.emplace();
    mapping::SlamStatistics& st = *result.statistics;
    st.scans = st.registeredByIcp = 3;
    result.trajectory = {{100.0, {}}, {101.5, {}}, {103.25, {}}};
    EXPECT_FALSE(mapping::openLoopAtEnd(result));
    EXPECT_EQ(mapping::formatSummary(result).find("WARNING"), std::string::npos);
    st.loopsUnconfirmed = 2;
    st.loopsOpenAtEnd = 1;
    st.largestOpenLoop = {0, 2, 4.35, mrpt::DEG2RAD(10.0)};
    EXPECT_TRUE(mapping::openLoopAtEnd(result));
    const std::string text = mapping::formatSummary(result);
    EXPECT_NE(text.find("WARNING: the log ends with 1 unconfirmed loop that would move the map: "
                        "the largest, from the scan at t = 103.250 s back to the one at t = "
                        "100.000 s (trajectory.txt stamps), is 4.35 m and 10.0 deg off it. "
                        "Either the map is open there or the scans match a look-alike place"),
              std::string::npos)
        << text;
    const nlohmann::json j = mapping::summaryJson(result);
    EXPECT_TRUE(j.at("open_loop_at_end").get<bool>());
    EXPECT_EQ(j.at("loops").at("unconfirmed").get<std::size_t>(), 2u);
    EXPECT_EQ(j.at("loops").at("open_at_end").get<std::size_t>(), 1u);
    const nlohmann::json& open = j.at("loops").at("largest_open_at_end");
    EXPECT_DOUBLE_EQ(open.at("from_stamp").get<double>(), 103.25);
    EXPECT_DOUBLE_EQ(open.at("to_stamp").get<double>(), 100.0);
    EXPECT_DOUBLE_EQ(open.at("distance_m").get<double>(), 4.35);
    EXPECT_NEAR(open.at("angle_deg").get<double>(), 10.0, 1e-9);
}

TEST(GraphSlam, ALoopFoundInTheLastKeyframesIsReportedOpen) {
    // Bormann's office_a toured by B3-sim's LDS-01 robot (a TurtleBot3's 3.5 m laser), seed
    // 41: a tree of corridors whose one loop is the tour's end, back at its start, 4.35 m and
    // 10 deg off the graph. A loop that corrects the graph needs a second, agreeing match, and
    // the log ends two searched keyframes later: the loop stays out, the map open (1.28 m), and
    // the summary must say so rather than pass the map off as closed. (Support from the
    // keyframes just before the loop mends this tour but confirms wrong loops elsewhere:
    // benchmarks.md, B3, "Tried, not kept (session 101)".)
    TOPOSLAM_SHARED_DATA_OR_SKIP(plan, "rooms/office_a_furnitures.png");
    const test::TempDir dir;
    const GeneratedTour tour = tourPlanByBenchRobot(dir, plan, "lds-01", 41);
    ASSERT_EQ(tour.sim.exitCode, 0) << tour.sim.output;
    const mapping::MappingResult result =
        mapping::mapLog(tour.log, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    ASSERT_TRUE(result.statistics);
    ASSERT_TRUE(mapping::openLoopAtEnd(result));
    const mapping::SlamStatistics::OpenLoop& open = result.statistics->largestOpenLoop;
    EXPECT_EQ(open.olderScan, 0u);  // back to where the tour started
    EXPECT_GT(open.currentScan, result.trajectory.size() * 9 / 10);
    // The map is open by what the loop says: the end of the estimated trajectory is off the
    // truth by about the loop's disagreement.
    const io::Trajectory2D truth = io::loadTrajectory(tour.groundTruth);
    ASSERT_EQ(result.trajectory.size(), truth.size());
    const CPose2D endOffStart = CPose2D(result.trajectory[open.currentScan].pose) -
                                CPose2D(result.trajectory[open.olderScan].pose);
    const CPose2D trueEndOffStart =
        CPose2D(truth[open.currentScan].pose) - CPose2D(truth[open.olderScan].pose);
    EXPECT_NEAR((endOffStart - trueEndOffStart).norm(), open.distance, 1.0);
    EXPECT_NE(mapping::formatSummary(result).find("WARNING: the log ends with 1 unconfirmed loop"),
              std::string::npos);
}

TEST(MappingOutputs, AnOdometryScaleOfExactlyOneIsEvidenceNotItsAbsence) {
    // The summary tells "too little evidence" from the flag, not from the estimate's value.
    mapping::MappingResult result;
    result.statistics.emplace();
    mapping::SlamStatistics& st = *result.statistics;
    st.scans = st.registeredByIcp = 100;
    st.odometryCalibrationDistance = 4;
    EXPECT_NE(mapping::formatSummary(result).find(
                  "odometry: distances as read (odometry_calibration off)\n"),
              std::string::npos)
        << mapping::formatSummary(result);
    st.odometryCalibrationDistance = 25;
    st.odometryScaleEstimated = true;  // the scans covered the distance: the odometry is exact
    EXPECT_NE(mapping::formatSummary(result).find("over 25 m of well-registered motion it read "
                                                  "0.0 % long"),
              std::string::npos)
        << mapping::formatSummary(result);
    EXPECT_TRUE(mapping::summaryJson(result).at("odometry").at("scale_estimated").get<bool>());
    result.odometryCalibration = true;
    EXPECT_NE(mapping::formatSummary(result).find("distances scaled by 1.0000, learnt from 25 m"),
              std::string::npos)
        << mapping::formatSummary(result);
}

TEST(MappingOutputs, ALogWhoseStampsWereLostHasNoRealTimeFactor) {
    mapping::MappingResult result;
    result.scans = 1001;
    result.wallSeconds = 2.0;
    result.logDuration = 100.0;  // 0.1 s a scan
    EXPECT_DOUBLE_EQ(*mapping::realTimeFactor(result), 50.0);
    EXPECT_NE(mapping::formatSummary(result).find("(50.0x real time)"), std::string::npos);
    result.logDuration = 0.001;  // stamps all 0, spaced 1 us apart by the reader
    EXPECT_FALSE(mapping::realTimeFactor(result));
    EXPECT_NE(mapping::formatSummary(result).find("the log's stamps do not tell its time"),
              std::string::npos)
        << mapping::formatSummary(result);
    EXPECT_TRUE(mapping::summaryJson(result).at("real_time_factor").is_null());
}

TEST(MappingOutputs, CountsAgreeInNumber) {
    mapping::MappingResult result;
    result.statistics.emplace();
    mapping::SlamStatistics& st = *result.statistics;
    st.scans = 101;
    st.registeredByIcp = 96;
    st.registeredByGraphMatcher = 3;
    st.registrationFailed = 1;
    st.submaps = st.optimizations = st.odometryJumps = st.loopCandidates = 1;
    st.odometryJumpsBetween = 1;
    st.odometryCatchUps = 2;
    st.odometryShortfallsBridged = st.odometryTranslationStalls = 1;
    const std::string summary = mapping::formatSummary(result);
    for (const char* phrase :
         {" in 1 submap;",
          "registration: 96 by ICP (96.0 %), 3 by the graph matcher (3.0 %), 1 failed (1.0 %, "
          "odometry kept)\n",
          "\n  odometry steps: 1 odometry jump (1 placed by ICP between the odometry's step and "
          "the last motion); 1 stall of the distance alone; 1 catch-up after short readings "
          "bridged; 2 odometry steps catching up after a stall\n",
          "loop closures: 1 candidate verified,", "(1 run)"}) {
        EXPECT_NE(summary.find(phrase), std::string::npos) << phrase << "\n" << summary;
    }
    // Only the cases that occurred are listed: nothing of ICP's, the matcher's or the failures'.
    for (const char* absent : {"  ICP:", "  graph matcher:", "  failed:", "(0 "})
        EXPECT_EQ(summary.find(absent), std::string::npos) << absent << "\n" << summary;
    // A count's parts follow it, each only where it is not 0.
    st.icpUnsettled = 4;
    st.icpSecondStarts = 1;
    st.icpHeldAlongHeading = 2;
    st.icpUnsettledRefused = 3;
    st.icpRefutedBeyondJump = 1;
    st.odometryJumps = 0;
    st.odometryJumpsBetween = 0;
    st.odometryTranslationStalls = 0;
    const std::string noJumps = mapping::formatSummary(result);
    EXPECT_NE(noJumps.find("\n  ICP: 4 unsettled (1 of them from a second start); 3 answers "
                           "refused (1 of them where ICP ended beyond a jump on clearly more of "
                           "the scan, 2 beyond the odometry's noise); 2 held at the odometry's "
                           "position along the heading\n"),
              std::string::npos)
        << noJumps;
    EXPECT_NE(noJumps.find("\n  odometry steps: 1 catch-up after short readings bridged; 2 "
                           "odometry steps catching up after a stall\n"),
              std::string::npos)
        << noJumps;
}

TEST(GraphSlam, ARobotLaserLogMapsTheRobotNotItsLaser) {
    // The bundled office log written as a new-style CARMEN log (ROBOTLASER1, as the Freiburg
    // clinic log): each line states the laser's pose (0.2 m ahead of the robot) and the
    // robot's. The trajectory is the robot's; taken for the laser's, it would be 0.2 m off at
    // every pose, turning with the robot.
    const test::TempDir dir;
    const std::string office = test::shareDir() + "/office/office";
    const auto records = io::LaserLogReader::readAll(office + ".rawlog");
    ASSERT_GT(records.size(), 300u);
    {
        std::FILE* f = std::fopen(dir.file("office.clf").c_str(), "w");
        ASSERT_NE(f, nullptr);
        for (const auto& r : records) {
            const auto& scan = *r.scan;
            const std::size_t n = scan.getScanSize();
            const CPose2D robot = r.odometry;
            const CPose2D laser = robot + CPose2D(scan.sensorPose);
            std::fprintf(f, "ROBOTLASER1 0 %.9f %.9f %.9f %.3f 0.01 0 %zu", -0.5 * scan.aperture,
                         scan.aperture, scan.aperture / static_cast<double>(n - 1), scan.maxRange,
                         n);
            for (std::size_t i = 0; i < n; ++i)
                std::fprintf(f, " %.4f",
                             scan.getScanRangeValidity(i) ? scan.getScanRange(i) : scan.maxRange);
            std::fprintf(f, " 0 %.9f %.9f %.9f %.9f %.9f %.9f 0 0 0 0 0 %.6f nohost %.6f\n",
                         laser.x(), laser.y(), laser.phi(), robot.x(), robot.y(), robot.phi(),
                         r.fileStamp, r.fileStamp);
        }
        std::fclose(f);
    }
    const mapping::MappingResult result = mapping::mapLog(
        dir.file("office.clf"), mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    const io::Trajectory2D truth = io::loadTrajectory(office + "_gt.txt");
    ASSERT_EQ(result.trajectory.size(), truth.size());
    const auto ate = evaluation::evaluateAbsoluteTrajectoryError(result.trajectory, truth);
    EXPECT_EQ(ate.matchedPoses, truth.size());
    EXPECT_LT(ate.position.rms, 0.03);  // 0.015 m; the rawlog itself maps to 0.019 m
}

TEST(GraphSlam, IntelHoldsTogetherWhenLoopsAreSearchedLessOften) {
    // intel, loops searched on every third keyframe instead of every second: the map broke in
    // its inner corridor (mean relation error 0.066 m, worst 0.94 m) after ICP moved the robot
    // 0.1 m along the corridor where its pose fitted a few more readings than the odometry's,
    // which the along-heading check then took (along_heading_margin 0.005). On simulated tours
    // such corrections were mostly wrong; a margin of a tenth of the readings holds them, and
    // intel with them: 0.015 / 0.13 m (shipped settings: 0.014 / 0.10 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/intel.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/intel.relations");
    const std::string shipped = test::readFile(test::configIni("toposlam-slam.ini"));
    const std::string text = std::regex_replace(shipped, std::regex("\nloop_search_every = [0-9]+"),
                                                "\nloop_search_every = 3");
    ASSERT_NE(text, shipped);
    const mapping::MappingResult result =
        mapping::mapLog(log, mrpt::config::CConfigFileMemory(text));
    const auto r = evaluation::evaluateRelativePoseError(result.trajectory,
                                                         evaluation::loadRelations(relations));
    EXPECT_EQ(r.matchedRelations, r.totalRelations);
    // Below icp-slam's 0.021 m and the issue's 0.018 m; no relation beyond its 0.3 m bound.
    EXPECT_LT(r.translation.mean, 0.018);
    EXPECT_LT(r.translation.max, 0.3);
    // The checks that decided it, as the summary lists them: each held one within the margin.
    mapping::GraphSlamOptions options;
    options.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "GraphSlam");
    ASSERT_TRUE(result.statistics.has_value());
    const auto& checks = result.statistics->alongHeadingChecks;
    std::size_t held = 0;
    for (std::size_t i = 0; i < checks.size(); ++i) {
        const mapping::AlongHeadingCheck& c = checks[i];
        EXPECT_LT(c.scan, result.trajectory.size());
        if (i > 0) {
            EXPECT_GT(c.scan, checks[i - 1].scan);
        }
        const double n = double(c.readings);
        const bool fitsNoBetter =
            double(c.onMapAtOdometry) + options.alongHeadingMargin * n >= double(c.onMapAtIcp);
        const bool seesThrough =
            double(c.seenThroughAtIcp) >=
            double(c.seenThroughAtOdometry) + options.alongHeadingFreeSpace * n;
        EXPECT_EQ(c.held, double(c.onMapAtIcp) >= 0.5 * n && (fitsNoBetter || seesThrough));
        EXPECT_EQ(c.heldForFreeSpace, c.held && !fitsNoBetter);
        held += c.held;
    }
    EXPECT_GE(held, 1u);  // three of its four (0.005 held one)
    EXPECT_GE(held, result.statistics->icpHeldAlongHeading);
}

/// `log` thinned as `conversion` says (alteration.keepEvery, alteration.keepBeamEvery: as a laser
/// with a lower scan rate or wider-spaced beams would record it), mapped with the shipped settings
/// and scored on `relations` (those whose stamps it keeps, at least `minMatched`): mean error below
/// `maxMean`, no relation beyond `maxWorst` (m).
void expectMappedWhenThinned(const std::string& log, const std::string& relations,
                             io::LogConversionOptions conversion, std::size_t minMatched,
                             double maxMean, double maxWorst) {
    test::TempDir dir;
    conversion.rawlogPath = dir.file("thinned.rawlog");
    io::convertLaserLog(log, conversion);
    const mapping::MappingResult result = mapping::mapLog(
        conversion.rawlogPath, mrpt::config::CConfigFile(test::configIni("toposlam-slam.ini")));
    const auto r = evaluation::evaluateRelativePoseError(result.trajectory,
                                                         evaluation::loadRelations(relations));
    EXPECT_GE(r.matchedRelations, minMatched);
    EXPECT_LT(r.translation.mean, maxMean);
    EXPECT_LT(r.translation.max, maxWorst);
}

/// One scan in three: mean below 0.1 m, no relation beyond the issue's 0.3 m.
void expectMappedAtAThirdOfTheScans(const std::string& log, const std::string& relations,
                                    std::size_t minMatched) {
    io::LogConversionOptions third;
    third.alteration.keepEvery = 3;
    expectMappedWhenThinned(log, relations, third, minMatched, 0.1, 0.3);
}

TEST(GraphSlam, Fr079HoldsTogetherAtAThirdOfItsScanRate) {
    // 0.3 m between scans, and fr079's odometry counts reversing as driving forward: where the
    // robot reverses in a corridor, ICP from the odometry (0.6 m off) ended 0.25 m sideways,
    // which registration rejects, and from the last motion it fitted 216 of 359 readings
    // against 146, short of the 25 % margin; the odometry's step was kept and the map broke
    // there (mean relation error 0.132 m, worst 0.667 m). ICP from the last motion that passes
    // where ICP from the odometry fails is now the answer: 0.062 / 0.20 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/fr079.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/fr079.relations");
    expectMappedAtAThirdOfTheScans(log, relations, 90);  // 95 of its 1685 relations are kept
}

TEST(GraphSlam, Fr079HoldsTogetherAtAQuarterOfItsScanRate) {
    // 0.4 m between scans. Around t = 1405 s a step fails both registrations and the odometry
    // kept leaves the graph a few degrees off; when the robot is back where it had been, every
    // right loop lies beyond the gate of the drift model (265 rejected) and the map stays broken
    // (mean relation error 0.157 m, worst 3.1 m). Matches that agree with each other beyond the
    // gate, from several searches and two visits (loop_contested_support, on by default since
    // session 57), repair it: 0.029 m, worst 0.14 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/fr079.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/fr079.relations");
    io::LogConversionOptions quarter;
    quarter.alteration.keepEvery = 4;
    expectMappedWhenThinned(log, relations, quarter, 200, 0.05, 0.3);  // 211 of 1685 kept
}

TEST(GraphSlam, MitCsailHoldsTogetherAtAThirdOfItsScanRate) {
    // 0.6 m between scans: every step beyond odometry_jump_distance (0.5 m). Judged on the
    // step alone, 492 of 663 were jumps, predicted by the last motion and left to the graph
    // matcher, and the map fell apart (mean relation error 5.4 m). A step like the last one is
    // no jump: 0.035 m, worst 0.11 m.
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/mit-csail.relations");
    expectMappedAtAThirdOfTheScans(log, relations, 25);  // 27 of its 1172 relations are kept
}

/// One beam in `n` of each scan (a coarser laser): every relation matched, mean below 0.05 m,
/// none beyond 0.5 m.
void expectMappedWithOneBeamIn(std::size_t n, const std::string& log,
                               const std::string& relations) {
    io::LogConversionOptions coarser;
    coarser.alteration.keepBeamEvery = n;
    expectMappedWhenThinned(log, relations, coarser, 1172, 0.05, 0.5);
}

TEST(GraphSlam, MitCsailHoldsTogetherWithEveryOtherBeam) {
    // 181 beams 1 deg apart instead of 361: loops at the end of the log were verified on 30
    // inliers, as for 0.5 deg, and went unverified, so the last minutes ended 2 m off (mean
    // relation error 0.145 m, worst 2.15 m). The graph matcher's min_inliers now counts beams
    // 0.5 deg apart (min_inliers_bearing_step_deg): 0.028 m, worst 0.42 m (a local glitch where
    // the odometry stalls; the full laser's worst is 0.29 m).
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/mit-csail.relations");
    expectMappedWithOneBeamIn(2, log, relations);
}

TEST(GraphSlam, MitCsailHoldsTogetherWithOneBeamInFour) {
    // 91 beams 2 deg apart, as a low-cost laser: broken in session 56's run (mean relation error
    // 0.755 m, worst 9.6 m); held in session 63's (0.031 m, worst 0.39 m), after the front end's
    // odometry rules of sessions 57-62 (not bisected).
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/mit-csail.relations");
    expectMappedWithOneBeamIn(4, log, relations);
}

TEST(GraphSlam, BadLogsGiveClearErrors) {
    test::TempDir dir;
    const mrpt::config::CConfigFile ini(test::configIni("toposlam-slam.ini"));
    // No scans at all.
    test::SimulatedDrive empty;
    test::writeRawlog(empty, dir.file("empty.rawlog"));
    EXPECT_THROW(mapping::mapLog(dir.file("empty.rawlog"), ini), io::InputError);
    // Scans without a single valid reading (laser blind).
    auto blind = test::simulateDrive(ringCorridor(), test::drivePath({{1.5, 1.5}, {3, 1.5}}), {});
    for (auto& s : blind.scans)
        blindScan(*s);
    test::writeRawlog(blind, dir.file("blind.rawlog"));
    try {
        mapping::mapLog(dir.file("blind.rawlog"), ini);
        ADD_FAILURE() << "a log without usable scans must be an error";
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("valid"), std::string::npos) << e.what();
    }
    // A gzip log cut in the middle.
    const auto ok =
        test::simulateDrive(ringCorridor(), test::drivePath({{1.5, 1.5}, {5, 1.5}}), {});
    test::writeRawlog(ok, dir.file("ok.rawlog.gz"));
    {
        std::ifstream in(dir.file("ok.rawlog.gz"), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(dir.file("cut.rawlog.gz"), std::ios::binary)
            << bytes.substr(0, bytes.size() / 2);
    }
    EXPECT_THROW(mapping::mapLog(dir.file("cut.rawlog.gz"), ini), io::InputError);
    // And the app says so and writes nothing.
    const auto r = test::runApp("toposlam-slam", "'" + test::configIni("toposlam-slam.ini") +
                                                     "' '" + dir.file("blind.rawlog") + "' -o '" +
                                                     dir.file("out") + "'");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("blind.rawlog"), std::string::npos) << r.output;
    EXPECT_FALSE(std::ifstream(dir.file("out/trajectory.txt")).good());
}

TEST(GraphSlam, NoLoopIntoTheOfficeNextToOneVisitedThreeTimes) {
    // The first office is entered three times, then the robot goes on into the next ones,
    // each 3 m along and alike. In the second, a match into the first from each of its visits
    // agrees with the others beyond the gate: from several visits, as after a front-end failure
    // (GraphSlam.AcceptsAgreeingLoopsBeyondTheGate). What tells them apart is the loop that
    // put the robot right in the corridor outside the first office a few metres earlier: the
    // group contradicts it by 3 m, more than that path can drift. Once (before that check)
    // such a group went in: 8 wrong loops, ATE 0.91 m. (The rule is on by default; set here
    // so that the test keeps it on.)
    const int rooms = 4;
    const double length = rooms * 3.0;
    for (const bool wander : {false, true}) {
        SCOPED_TRACE(wander ? "down the corridor and back first" : "straight on");
        std::vector<mrpt::math::TPoint2D> path = threeVisitsOfTheFirstOffice();
        if (wander)
            path.push_back({length - 0.8, 1.0});
        for (int r = 1; r < rooms; ++r)
            roundNarrowOffice(path, r * 3.0);
        path.push_back({length - 0.8, 1.0});
        path.push_back({0.8, 1.0});
        const auto truth = test::drivePath(path);
        const auto drive =
            test::simulateDrive(narrowIdenticalRooms(rooms), truth, officeOdometryErrors(), 5);
        const SlamRun run =
            runSlam(drive, 0, [](mapping::GraphSlamOptions& o) { o.loopContestedSupport = 4; });
        EXPECT_EQ(wrongLoops(*run.slam, truth), 0u);
        EXPECT_EQ(run.slam->statistics().loopsContested, 0u);
        EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.1);
    }
}

TEST(GraphSlam, NoLoopIntoALookAlikeOfficeThroughItsBackDoor) {
    // The same offices between two corridors. The first is entered three times from the front
    // corridor; then the robot walks on to the end, round into the back corridor and into the
    // second office by its back door, 30 m through corridors it has not been in. In there,
    // matches into every visit of the first agree with each other beyond the gate, from two or
    // more visits and several searches: to the contested-loop rule they looked just like a
    // front end that failed on the way (21 wrong loops, ATE 1.0 m with
    // loop_contested_support = 4), which is why the shipped settings kept it off. What tells
    // them apart: the robot got there on scans ICP placed, so the graph is as right as its
    // covariances say; a group is accepted only past a keyframe the front end doubts (placed
    // by the graph matcher or the odometry). Without that rule: 16 wrong loops, ATE 0.99 m
    // (10-33 and 0.8-1.1 m in 15 of 16 seeds and odometries tried; 0 and under 1 cm with it).
    const int rooms = 4;
    const double length = rooms * 3.0;
    std::vector<mrpt::math::TPoint2D> path = threeVisitsOfTheFirstOffice();
    for (const mrpt::math::TPoint2D& p : std::vector<mrpt::math::TPoint2D>{{length + 1.0, 1.0},
                                                                           {length + 1.0, 7.0},
                                                                           {4.5, 7.0},
                                                                           {4.5, 3.0},
                                                                           {3.7, 3.0},
                                                                           {3.7, 5.0},
                                                                           {4.5, 5.0},
                                                                           {4.5, 1.0},
                                                                           {0.8, 1.0}})
        path.push_back(p);
    const auto truth = test::drivePath(path);
    const auto drive =
        test::simulateDrive(officesBetweenTwoCorridors(rooms), truth, officeOdometryErrors(), 5);
    const SlamRun run = runSlam(drive);
    EXPECT_EQ(wrongLoops(*run.slam, truth), 0u);
    EXPECT_LT(test::absoluteTrajectoryError(truth, run.poses), 0.1);
}
