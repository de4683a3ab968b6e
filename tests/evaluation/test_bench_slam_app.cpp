// End-to-end tests of toposlam-bench-slam (benchmark B3) on the simulated office and on tours
// of a drawn plan (--sim-plans), whose ground truth is exact: every engine's row, the JSON,
// the pictures, the simulated robots, and the exit statuses.
#include "OfficeLaserRelations.h"

#include <gtest/gtest.h>
#include <toposlam/evaluation/ChildProcess.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/Trajectory.h>
#include <nlohmann/json.hpp>

#include <TestSupport.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

using toposlam::evaluation::odometryAtScans;
using toposlam::test::runApp;
using toposlam::test::runCommand;
using toposlam::test::TempDir;
namespace fs = std::filesystem;

namespace {

using toposlam::test::contains;

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

std::string bench() {
    return "'" + toposlam::test::binDir() + "/toposlam-bench-slam' ";
}

// A run that finished on the office: its relations all matched, sensible resource figures.
void expectScored(const nlohmann::json& run, std::size_t relations, double maxAte) {
    SCOPED_TRACE(run.value("engine", "?"));
    ASSERT_EQ(run["status"], "ok") << run.dump(2);
    const nlohmann::json& accuracy = run["accuracy"];
    EXPECT_EQ(accuracy["relations_total"], relations);
    EXPECT_EQ(accuracy["relations_matched"], relations);
    EXPECT_LT(accuracy["ate"]["position_m"]["rms"].get<double>(), maxAte);
    EXPECT_LT(accuracy["translation_m"]["mean"].get<double>(), 0.05);
    const nlohmann::json& process = run["process"];
    EXPECT_EQ(process["exit_code"], 0);
    EXPECT_GT(process["cpu_s"].get<double>(), 0.0);
    EXPECT_GT(process["wall_s"].get<double>(), 0.0);
    // An MRPT SLAM process holding a 368-scan log and its map: tens to hundreds of MiB.
    EXPECT_GT(process["peak_rss_mib"].get<double>(), 10.0);
    EXPECT_LT(process["peak_rss_mib"].get<double>(), 2000.0);
}

// toposlam-bench-slam on the office alone, graph engine, with `options` (a log alteration):
// its table row and JSON name the altered log `name`, whose JSON entry goes to `log`.
void runOnAlteredOffice(const std::string& options, const std::string& name, nlohmann::json& log) {
    TempDir dir;
    const std::string json = dir.file("b3.json");
    const auto r = runApp("toposlam-bench-slam",
                          "--logs office --engines graph " + options + " --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "| " + name + " | graph")) << r.output;
    const nlohmann::json j = readJson(json);
    ASSERT_EQ(j["logs"].size(), 1u);
    log = j["logs"][0];
    EXPECT_EQ(log["name"], name);
}

}  // namespace

TEST(BenchSlamApp, HelpExplainsEveryOption) {
    const auto r = runApp("toposlam-bench-slam", "--help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* option : {"--data",        "--logs",       "--engines",
                               "--config",      "--icp-slam",   "--icp-slam-config",
                               "--keep",        "--mirror",     "--images",
                               "--json",        "--timeout",    "Kuemmerle",
                               "icp-slam",      "office",       "--sim-plans",
                               "--sim-robots",  "--sim-dir",    "--sim-config",
                               "lms1xx",        "lms200",       "urg-04lx",
                               "poor-odometry", "people",       "stalling-odometry",
                               "lds-01",        "--robot-frame"}) {
        EXPECT_TRUE(contains(r.output, option)) << option;
    }
}

TEST(BenchSlamApp, OfficeEveryEngineScoredAgainstGroundTruth) {
    TempDir dir;
    const std::string tmp = dir.file("tmp"), json = dir.file("b3.json"), images = dir.file("img");
    fs::create_directories(tmp);
    const auto r = runCommand("TMPDIR='" + tmp + "' " + bench() + "--logs office --json " + json +
                              " --images " + images);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* row : {"| office | graph |", "| office | icp |", "| office | icp-slam |",
                            "[1/", "office graph ...", "ATE RMSE"}) {
        EXPECT_TRUE(contains(r.output, row)) << row << "\n" << r.output;
    }
    EXPECT_TRUE(fs::is_empty(tmp)) << "the runs' temporary folder was left behind";

    const nlohmann::json j = readJson(json);
    ASSERT_EQ(j["logs"].size(), 1u);
    const nlohmann::json& office = j["logs"][0];
    EXPECT_EQ(office["name"], "office");
    EXPECT_EQ(office["reference"]["kind"], "ground_truth");
    EXPECT_EQ(office["scans"], 368);
    const std::size_t relations = office["reference"]["relations"];
    EXPECT_GT(relations, 368u);  // every consecutive pair + the multi-scale ones
    ASSERT_EQ(office["runs"].size(), 3u);
    const nlohmann::json& graph = office["runs"][0];
    EXPECT_EQ(graph["engine"], "graph");
    // Graph SLAM on a simulated log with 1 cm laser noise: centimetres, not decimetres.
    expectScored(graph, relations, 0.1);
    EXPECT_EQ(graph["summary"]["engine"], "graph");
    EXPECT_EQ(graph["summary"]["scans"], 368);
    EXPECT_TRUE(graph["summary"]["loops"].contains("accepted"));
    // MRPT's ICP builder, our wrapper and the stock app: no loop closure, so looser.
    EXPECT_EQ(office["runs"][1]["engine"], "icp");
    expectScored(office["runs"][1], relations, 0.2);
    const nlohmann::json& icpSlam = office["runs"][2];
    EXPECT_EQ(icpSlam["engine"], "icp-slam");
    if (toposlam::evaluation::findExecutable("icp-slam").empty()) {
        EXPECT_EQ(icpSlam["status"], "skipped");
    } else {
        expectScored(icpSlam, relations, 0.2);
        EXPECT_EQ(icpSlam["conversion"]["exit_code"], 0);
    }
    for (const char* picture : {"office-maps.png", "office-trajectories.png"}) {
        const cv::Mat image = cv::imread(images + "/" + picture);
        ASSERT_FALSE(image.empty()) << picture;
        EXPECT_GT(image.cols, 300) << picture;
    }
}

TEST(BenchSlamApp, KeepEveryRunsTheLogsWithFewerScans) {
    nlohmann::json office;
    ASSERT_NO_FATAL_FAILURE(runOnAlteredOffice("--keep-every 2", "office-1in2", office));
    EXPECT_EQ(office["scans"], 184) << "every second of the office's 368 scans";
    // Scored on the relations between kept scans only (85 of the 638 derived from the
    // ground truth: their two stamps must both be kept), still to centimetres.
    const nlohmann::json& graph = office["runs"][0];
    ASSERT_EQ(graph["status"], "ok") << graph.dump(2);
    const std::size_t matched = graph["accuracy"]["relations_matched"];
    EXPECT_GT(matched, 50u);
    EXPECT_LT(matched, graph["accuracy"]["relations_total"].get<std::size_t>());
    EXPECT_LT(graph["accuracy"]["translation_m"]["mean"].get<double>(), 0.05);
    EXPECT_LT(graph["accuracy"]["ate"]["position_m"]["rms"].get<double>(), 0.1);
}

TEST(BenchSlamApp, MirrorMapsTheMirrorImageScoredOnTheMirroredGroundTruth) {
    // The office toured in its mirror image: mapped as well as the office itself (the same
    // bound as above), which it could not be if the ground truth were not mirrored with it (no
    // rigid motion turns a mirror image into the original: metres of ATE).
    nlohmann::json office;
    ASSERT_NO_FATAL_FAILURE(runOnAlteredOffice("--mirror", "office-mirrored", office));
    EXPECT_EQ(office["scans"], 368);
    EXPECT_EQ(office["reference"]["kind"], "ground_truth");
    expectScored(office["runs"][0], office["reference"]["relations"], 0.1);
}

TEST(BenchSlamApp, RelationsAreScoredAtTheLaserTheLogStates) {
    // The office as a relation log, its relations made at its laser (0.2 m ahead of the
    // robot's centre), as Kuemmerle et al.'s are: toposlam-slam gives the robot's poses, and
    // they are moved to the laser before scoring. Scored as given they would be off by up to
    // 0.4 m on its turns (EvalSlamApp.LaserFrameOf...). The data folder is given relative to
    // the working directory, which the runs' child processes do not share.
    TempDir dir;
    fs::create_directories(dir.file("data"));
    fs::create_symlink(toposlam::test::shareDir() + "/office/office.rawlog",
                       dir.file("data/officelaser.rawlog"));
    toposlam::evaluation::test_paths::writeOfficeLaserRelations(
        dir.file("data/officelaser.relations"));
    const auto r = runCommand("cd '" + dir.file("") + "' && " + bench() +
                              "-d data --logs officelaser --engines graph --json b3.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output,
                         "scored at the laser, 0.200 m ahead and 0.000 m left of the "
                         "robot's centre"))
        << r.output;
    const nlohmann::json log = readJson(dir.file("b3.json"))["logs"][0];
    EXPECT_NEAR(log["reference"]["laser_position_m"][0].get<double>(), 0.2, 1e-6);
    const nlohmann::json& graph = log["runs"][0];
    ASSERT_EQ(graph["status"], "ok") << graph.dump(2);
    EXPECT_EQ(graph["accuracy"]["relations_unmatched"], 0);
    // As on the office scored against its ground truth (expectScored's bound is 0.05 m).
    EXPECT_LT(graph["accuracy"]["translation_m"]["mean"].get<double>(), 0.02);

    // --robot-frame scores the poses as given, for relations made in the robot's frame.
    const auto robot = runCommand("cd '" + dir.file("") + "' && " + bench() +
                                  "-d data --logs officelaser --engines graph --robot-frame "
                                  "--json robot.json");
    ASSERT_EQ(robot.exitCode, 0) << robot.output;
    EXPECT_FALSE(contains(robot.output, "scored at the laser")) << robot.output;
    const nlohmann::json asGiven = readJson(dir.file("robot.json"))["logs"][0];
    EXPECT_TRUE(asGiven["reference"]["laser_position_m"].is_null());
    EXPECT_GT(asGiven["runs"][0]["accuracy"]["translation_m"]["mean"].get<double>(), 0.05);
}

TEST(BenchSlamApp, KeepEveryOnABadLogFailsItsRowNamingTheProblem) {
    // The conversion to fewer scans reads the log first: a NaN reading is that log's error,
    // not a crash, and nothing is left beside the data.
    TempDir dir;
    const std::string data = dir.file("data");
    fs::create_directories(data);
    toposlam::test::writeText(data + "/bad.clf",
                              "FLASER 3 1.0 nan 2.0 0 0 0 0 0 0 1.0 nohost 1.0\n");
    toposlam::test::writeText(data + "/bad.relations", "1.0 2.0 0 0 0 0 0 0\n");
    const auto r =
        runApp("toposlam-bench-slam", "-d " + data + " --logs bad --engines graph --keep-every 2");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "bad.clf: line 1: reading 1 is nan")) << r.output;
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(data))
        ++files;
    EXPECT_EQ(files, 2u) << "the data folder holds only what the test wrote";
}

TEST(BenchSlamApp, KeepKeepsEveryRunsFolder) {
    TempDir dir;
    const std::string keep = dir.file("runs");
    const auto r = runApp("toposlam-bench-slam", "--logs office --engines icp --keep " + keep);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string run = keep + "/office/icp";
    std::ifstream ini(run + "/toposlam-slam.ini");
    const std::string text((std::istreambuf_iterator<char>(ini)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(contains(text, "engine=icp") || contains(text, "engine = icp")) << text;
    for (const char* file :
         {"out/trajectory.txt", "out/map.png", "out/summary.json", "stdout.txt", "stderr.txt"}) {
        EXPECT_TRUE(fs::is_regular_file(run + "/" + file)) << file;
    }
}

TEST(BenchSlamApp, MissingDataIsSkipped) {
    TempDir dir;
    const auto r = runApp("toposlam-bench-slam",
                          "--data " + dir.file("absent") + " --json " + dir.file("b3.json"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "B3 skipped")) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("b3.json")));
}

TEST(BenchSlamApp, BadUsageExits2) {
    for (const char* args : {"--no-such-option", "--logs office --engines graph,cartographer",
                             "--logs office,office", "--logs office --timeout -1"}) {
        const auto r = runApp("toposlam-bench-slam", args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_TRUE(contains(r.output, "error: ")) << args << "\n" << r.output;
    }
}

TEST(BenchSlamApp, MissingConfigIsBadInput) {
    const auto r = runApp("toposlam-bench-slam", "--logs office --config /nonexistent/slam.ini");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "error: /nonexistent/slam.ini: configuration file not found"))
        << r.output;
}

TEST(BenchSlamApp, FailingRunIsReportedInItsRowAndExits1) {
    TempDir dir;
    const std::string json = dir.file("b3.json");
    const auto r = runApp("toposlam-bench-slam",
                          "--logs office --engines icp-slam --icp-slam /bin/false --json " + json);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "| office | icp-slam | FAILED [1] |")) << r.output;
    EXPECT_TRUE(contains(r.output, "[1] office icp-slam: icp-slam: exit status 1")) << r.output;
    const nlohmann::json j = readJson(json);
    EXPECT_EQ(j["logs"][0]["runs"][0]["status"], "failed");
}

TEST(BenchSlamApp, AbsentIcpSlamIsNotRun) {
    const auto r = runApp("toposlam-bench-slam",
                          "--logs office --engines icp-slam --icp-slam /nonexistent/icp-slam");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "| office | icp-slam | not run [1] |")) << r.output;
    EXPECT_TRUE(contains(r.output, "not installed")) << r.output;
}

namespace {

// A drawn plan (white free, black walls, a grey table): two 5 x 4 m rooms joined by a 0.9 m
// door, 5 cm pixels, black outside the building (no free space to tour there).
std::string writeTwoRoomPlan(const std::string& directory) {
    cv::Mat plan(100, 240, CV_8U, cv::Scalar(0));
    plan(cv::Rect(10, 10, 100, 80)).setTo(255);
    plan(cv::Rect(114, 10, 100, 80)).setTo(255);
    plan(cv::Rect(110, 40, 4, 18)).setTo(255);   // the door
    plan(cv::Rect(150, 20, 24, 14)).setTo(128);  // a table
    const std::string path = directory + "/two_rooms_furnitures.png";
    cv::imwrite(path, plan);
    return path;
}

// toposlam-bench-slam, graph engine, on the tours of `plan` that `tours` asks for (--sim-robots,
// --sim-seeds), logs into `logs`, results into `json`.
toposlam::test::CommandResult benchSimulatedTours(const std::string& plan, const std::string& tours,
                                                  const std::string& logs,
                                                  const std::string& json) {
    return runApp("toposlam-bench-slam", "--sim-plans " + plan + " " + tours +
                                             " --engines graph --sim-dir " + logs + " --json " +
                                             json);
}

// Every one of `lines` is in `output`.
void expectPrinted(const std::string& output, std::initializer_list<const char*> lines) {
    for (const char* text : lines)
        EXPECT_TRUE(contains(output, text)) << text << "\n" << output;
}

double pathLength(const toposlam::io::Trajectory2D& path) {
    double length = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
        length +=
            std::hypot(path[i].pose.x - path[i - 1].pose.x, path[i].pose.y - path[i - 1].pose.y);
    return length;
}

}  // namespace

// --sim-plans: each plan toured by each robot, with that robot's laser and odometry, and every
// engine scored on those logs against their exact ground truth.
TEST(BenchSlamApp, SimulatedPlansAreTouredByEveryRobotAndScored) {
    TempDir tmp;
    const std::string plan = writeTwoRoomPlan(tmp.path());
    const std::string logs = tmp.path() + "/logs", json = tmp.path() + "/b3.json";
    const auto r = benchSimulatedTours(plan, "--sim-robots lms200,poor-odometry", logs, json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectPrinted(
        r.output,
        {"simulating 1/2: two_rooms.lms200 ...", "simulating 2/2: two_rooms.poor-odometry ...",
         "| two_rooms.lms200 | graph |", "| two_rooms.poor-odometry | graph |"});
    // Without --logs only the simulated logs run.
    EXPECT_FALSE(contains(r.output, "| office |")) << r.output;

    const nlohmann::json j = readJson(json);
    ASSERT_EQ(j["logs"].size(), 2u);
    for (const nlohmann::json& log : j["logs"]) {
        SCOPED_TRACE(log["name"].get<std::string>());
        EXPECT_EQ(log["reference"]["kind"], "ground_truth");
        ASSERT_EQ(log["runs"].size(), 1u);
        // Two small rooms and a 1-2 cm laser: the map is exact to a few cm.
        expectScored(log["runs"][0], log["reference"]["relations"], 0.05);
    }

    // The lms200 log has that laser: 181 beams over 180 deg, 8 m.
    toposlam::io::LaserLogReader reader(logs + "/two_rooms.lms200.rawlog");
    toposlam::io::LaserLogRecord record;
    ASSERT_TRUE(reader.next(record));
    EXPECT_EQ(record.scan->getScanSize(), 181u);
    EXPECT_NEAR(record.scan->aperture, M_PI, 1e-6);
    EXPECT_NEAR(record.scan->maxRange, 8.0, 1e-6);
    // Each log's odometry has its robot's error model: the simulator's 1 % long, and 5 %.
    for (const auto& [robot, scale] : {std::pair{"lms200", 1.01}, {"poor-odometry", 1.05}}) {
        const std::string base = logs + "/two_rooms." + robot;
        const double odometry = pathLength(odometryAtScans(base + ".rawlog"));
        const double truth = pathLength(toposlam::io::loadTrajectory(base + "_gt.txt"));
        ASSERT_GT(truth, 5.0) << robot;
        // Its random error only lengthens the path (1.4 and 6.2 % long as simulated).
        EXPECT_GT(odometry / truth, scale - 0.005) << robot;
        EXPECT_LT(odometry / truth, scale + 0.025) << robot;
    }
}

// --sim-seeds: every plan and robot toured once per seed (other noise and odometry errors on
// the same tour), and the table by robot sums the tours up.
TEST(BenchSlamApp, SimulatedToursRepeatWithEverySeedAndAreSummedUpByRobot) {
    TempDir tmp;
    const std::string plan = writeTwoRoomPlan(tmp.path());
    const std::string logs = tmp.path() + "/logs", json = tmp.path() + "/b3.json";
    const auto r = benchSimulatedTours(plan, "--sim-robots lms200 --sim-seeds 1,2", logs, json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectPrinted(
        r.output,
        {"simulating 1/2: two_rooms.lms200.seed1 ...", "simulating 2/2: two_rooms.lms200.seed2 ...",
         "| two_rooms.lms200.seed1 | graph |", "| two_rooms.lms200.seed2 | graph |",
         "Simulated logs by robot", "| lms200 | graph | 2 / 2 |"});
    // The seeds give other logs of the same tour: other odometry, the same true path.
    const auto odometry1 = odometryAtScans(logs + "/two_rooms.lms200.seed1.rawlog");
    const auto odometry2 = odometryAtScans(logs + "/two_rooms.lms200.seed2.rawlog");
    ASSERT_EQ(odometry1.size(), odometry2.size());
    EXPECT_NE(pathLength(odometry1), pathLength(odometry2));
    EXPECT_DOUBLE_EQ(
        pathLength(toposlam::io::loadTrajectory(logs + "/two_rooms.lms200.seed1_gt.txt")),
        pathLength(toposlam::io::loadTrajectory(logs + "/two_rooms.lms200.seed2_gt.txt")));

    // The summary is the two logs' ATE: mean, median, worst.
    const nlohmann::json j = readJson(json);
    ASSERT_EQ(j["logs"].size(), 2u);
    std::vector<double> ates;
    for (const nlohmann::json& log : j["logs"])
        ates.push_back(log["runs"][0]["accuracy"]["ate"]["position_m"]["rms"].get<double>());
    ASSERT_EQ(j["by_robot"].size(), 1u);
    const nlohmann::json& g = j["by_robot"][0];
    EXPECT_EQ(g["robot"], "lms200");
    EXPECT_EQ(g["engine"], "graph");
    EXPECT_EQ(g["scored"], 2);
    EXPECT_NEAR(g["ate_rms_mean_m"].get<double>(), 0.5 * (ates[0] + ates[1]), 1e-12);
    EXPECT_NEAR(g["ate_rms_median_m"].get<double>(), 0.5 * (ates[0] + ates[1]), 1e-12);
    EXPECT_NEAR(g["ate_rms_max_m"].get<double>(), std::max(ates[0], ates[1]), 1e-12);
    EXPECT_EQ(g["worst_log"],
              ates[0] >= ates[1] ? "two_rooms.lms200.seed1" : "two_rooms.lms200.seed2");
    EXPECT_LT(g["ate_rms_max_m"].get<double>(), 0.05);  // two small rooms, a 1 cm laser

    // A seed given twice would name two logs alike; a seed that is not one is bad usage.
    auto bad =
        runApp("toposlam-bench-slam",
               "--sim-plans " + plan + " --sim-robots lms200 --sim-seeds 1,1 --sim-dir " + logs);
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_TRUE(contains(bad.output, "two logs would be named two_rooms.lms200.seed1"))
        << bad.output;
    bad = runApp("toposlam-bench-slam", "--sim-plans " + plan + " --sim-seeds x");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_TRUE(contains(bad.output, "--sim-seeds: ")) << bad.output;
}

TEST(BenchSlamApp, SimulatedLogsRunAfterThoseOfLogs) {
    TempDir tmp;
    const std::string plan = writeTwoRoomPlan(tmp.path());
    const auto r =
        runApp("toposlam-bench-slam", "--logs office --engines graph --sim-plans " + plan +
                                          " --sim-robots lms200 --sim-dir " + tmp.path() + "/logs");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto office = r.output.find("| office | graph |");
    const auto simulated = r.output.find("| two_rooms.lms200 | graph |");
    ASSERT_NE(office, std::string::npos) << r.output;
    ASSERT_NE(simulated, std::string::npos) << r.output;
    EXPECT_LT(office, simulated) << r.output;
}

TEST(BenchSlamApp, UnknownRobotOrMissingPlanIsAnError) {
    TempDir tmp;
    auto r = runApp("toposlam-bench-slam", "--sim-plans office_d --sim-robots lms200,roomba");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(contains(r.output, "--sim-robots: unknown robot 'roomba'")) << r.output;
    r = runApp("toposlam-bench-slam",
               "--sim-plans /nonexistent/plan.png --sim-dir " + tmp.path() + "/logs");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "/nonexistent/plan.png: floor plan not found")) << r.output;
    r = runApp("toposlam-bench-slam", "--sim-plans office_d,office_d --sim-robots lms200");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(contains(r.output, "two logs would be named office_d.lms200")) << r.output;
    // A plan with no free space to tour: the simulation fails, and the message says where.
    const std::string solid = tmp.path() + "/solid.png";
    cv::imwrite(solid, cv::Mat(40, 40, CV_8U, cv::Scalar(0)));
    r = runApp("toposlam-bench-slam",
               "--sim-plans " + solid + " --sim-robots urg-04lx --sim-dir " + tmp.path() + "/logs");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(
        contains(r.output, "toposlam-sim on " + solid + " with robot urg-04lx: exit status"))
        << r.output;
}
