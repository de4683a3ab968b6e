// The pieces of benchmark B3 (toposlam-bench-slam) on small inputs made here: child processes
// and their resource use, .ini copies with a key changed, finding the logs, choosing what to
// run, the side-by-side map picture and the report.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/evaluation/ChildProcess.h>
#include <toposlam/evaluation/IniWithSettings.h>
#include <toposlam/evaluation/MapComparisonImage.h>
#include <toposlam/evaluation/SlamBenchmark.h>
#include <toposlam/evaluation/SlamBenchmarkLog.h>
#include <toposlam/evaluation/SlamBenchmarkReport.h>
#include <toposlam/evaluation/TrajectoryPlot.h>
#include <toposlam/io/InputError.h>

#include <TestSupport.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

using namespace toposlam::evaluation;
using toposlam::test::TempDir;
namespace fs = std::filesystem;

namespace {

using toposlam::test::readFile;

void touch(const std::string& path, const std::string& text = "x\n") {
    std::ofstream(path) << text;
}

using toposlam::test::contains;

}  // namespace

// ---- ChildProcess -------------------------------------------------------------------------

TEST(ChildProcess, ExitStatusOutputAndWorkingDirectory) {
    TempDir dir;
    ChildProcessSpec spec;
    spec.argv = {"sh", "-c", "pwd; echo oops >&2; exit 3"};
    spec.workingDirectory = dir.path();
    spec.stdoutFile = dir.file("out.txt");
    spec.stderrFile = dir.file("err.txt");
    const ChildProcessResult r = runChildProcess(spec);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_FALSE(r.succeeded());
    EXPECT_EQ(r.describeFailure(), "exit status 3");
    EXPECT_EQ(readFile(dir.file("out.txt")), fs::canonical(dir.path()).string() + "\n");
    EXPECT_EQ(readFile(dir.file("err.txt")), "oops\n");
    EXPECT_GT(r.peakRssBytes, 0u);
}

TEST(ChildProcess, StdinIsEmptySoKeyPressWaitsEnd) {
    TempDir dir;
    ChildProcessSpec spec;
    spec.argv = {"sh", "-c", "read line; echo \"read status $?\""};
    spec.stdoutFile = dir.file("out.txt");
    const ChildProcessResult r = runChildProcess(spec);
    EXPECT_TRUE(r.succeeded());
    EXPECT_EQ(readFile(dir.file("out.txt")), "read status 1\n");
}

TEST(ChildProcess, CpuTimeIsTheChildsOwn) {
    ChildProcessSpec spec;
    // About 0.2 s or more of CPU in the child; the parent only waits.
    spec.argv = {"sh", "-c", "i=0; while [ $i -lt 100000 ]; do i=$((i+1)); done"};
    const ChildProcessResult r = runChildProcess(spec);
    ASSERT_TRUE(r.succeeded());
    EXPECT_GT(r.cpuSeconds(), 0.0);
    EXPECT_GE(r.wallSeconds, r.cpuSeconds() * 0.5);  // one thread: CPU cannot exceed wall much
}

TEST(ChildProcess, SignalTimeoutAndMissingProgram) {
    ChildProcessSpec killed;
    killed.argv = {"sh", "-c", "kill -SEGV $$"};
    const ChildProcessResult k = runChildProcess(killed);
    EXPECT_EQ(k.signal, SIGSEGV);
    EXPECT_TRUE(contains(k.describeFailure(), "signal 11")) << k.describeFailure();

    ChildProcessSpec slow;
    slow.argv = {"sleep", "30"};
    slow.timeoutSeconds = 0.2;
    const ChildProcessResult s = runChildProcess(slow);
    EXPECT_TRUE(s.timedOut);
    EXPECT_FALSE(s.succeeded());
    EXPECT_LT(s.wallSeconds, 25.0);

    ChildProcessSpec missing;
    missing.argv = {"/nonexistent/program"};
    const ChildProcessResult m = runChildProcess(missing);
    EXPECT_TRUE(m.execFailed);
    EXPECT_EQ(m.exitCode, 127);
    EXPECT_TRUE(contains(m.describeFailure(), "could not start")) << m.describeFailure();
}

TEST(ChildProcess, FindExecutable) {
    TempDir dir;
    touch(dir.file("plain.txt"));
    fs::permissions(dir.file("plain.txt"), fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_FALSE(findExecutable("sh").empty());
    EXPECT_EQ(findExecutable("/bin/sh"), "/bin/sh");
    EXPECT_EQ(findExecutable("no-such-program-toposlam"), "");
    EXPECT_EQ(findExecutable(dir.file("plain.txt")), "");  // not executable
    EXPECT_EQ(findExecutable(dir.path()), "");             // a folder
}

// ---- IniWithSettings ----------------------------------------------------------------------

TEST(IniWithSettings, CopyReadsLikeTheOriginalExceptTheChangedKeys) {
    TempDir dir;
    const std::string source = toposlam::test::configIni("toposlam-slam.ini");
    const std::string copy = dir.file("icp.ini");
    writeIniWithSettings(source, copy,
                         {{"Slam", "engine", "icp"}, {"NewSection", "new_key", "42"}});
    const mrpt::config::CConfigFile original(source), changed(copy);
    EXPECT_EQ(changed.read_string("Slam", "engine", ""), "icp");
    EXPECT_EQ(changed.read_int("NewSection", "new_key", 0), 42);
    std::vector<std::string> sections;
    original.getAllSections(sections);
    ASSERT_GT(sections.size(), 3u);
    for (const std::string& section : sections) {
        std::vector<std::string> keys;
        original.getAllKeys(section, keys);
        for (const std::string& key : keys) {
            if (section == "Slam" && key == "engine")
                continue;
            EXPECT_EQ(changed.read_string(section, key, "<absent>"),
                      original.read_string(section, key, ""))
                << section << "/" << key;
        }
    }
    EXPECT_DOUBLE_EQ(readIniNumber(copy, "NewSection", "new_key", 0), 42.0);
    EXPECT_DOUBLE_EQ(readIniNumber(copy, "NewSection", "absent", 0.05), 0.05);
    EXPECT_THROW(writeIniWithSettings(dir.file("none.ini"), copy, {}), toposlam::io::InputError);
}

// ---- logs and selection -------------------------------------------------------------------

TEST(SlamBenchmarkLogs, FindsLogsWithRelations) {
    TempDir dir;
    touch(dir.file("b.relations"));
    touch(dir.file("b.clf"));
    touch(dir.file("a.relations"));
    touch(dir.file("a.rawlog.gz"));
    touch(dir.file("orphan.relations"));  // no log
    touch(dir.file("c.clf"));             // no relations
    const auto logs = findRelationLogs(dir.path());
    ASSERT_EQ(logs.size(), 2u);
    EXPECT_EQ(logs[0].name, "a");
    EXPECT_EQ(logs[0].logFile, dir.file("a.rawlog.gz"));
    EXPECT_EQ(logs[1].name, "b");
    EXPECT_EQ(logs[1].relationsFile, dir.file("b.relations"));
    EXPECT_TRUE(findRelationLogs(dir.file("absent")).empty());
}

TEST(SlamBenchmarkSelection, SkipsWithoutDataUnlessOnlySimulatedLogsAreAsked) {
    SlamBenchmarkOptions options;
    options.dataDir = "/nonexistent/slam";
    options.simulatedLogs = {{"office", "office.rawlog", "", "office_gt.txt", ""}};
    options.setup.icpSlam = "";
    EXPECT_FALSE(SlamBenchmark(options).skipReason().empty());
    options.logs = {"intel"};
    EXPECT_TRUE(contains(SlamBenchmark(options).skipReason(), "/nonexistent/slam"));
    options.logs = {"office"};
    const SlamBenchmark office(options);
    EXPECT_TRUE(office.skipReason().empty());
    ASSERT_EQ(office.logs().size(), 1u);
    // icp-slam not installed: not a run (its row is reported as not run).
    const auto runs = office.runs();
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].second, SlamEngine::Graph);
    EXPECT_EQ(runs[1].second, SlamEngine::Icp);
}

TEST(SlamBenchmarkSelection, UnknownOrRepeatedNamesAreUsageErrors) {
    TempDir dir;
    touch(dir.file("intel.relations"));
    touch(dir.file("intel.clf"));
    SlamBenchmarkOptions options;
    options.dataDir = dir.path();
    options.simulatedLogs = {{"office", "office.rawlog", "", "office_gt.txt", ""}};
    options.setup.icpSlam = "/usr/bin/icp-slam";
    EXPECT_EQ(SlamBenchmark(options).logs().size(), 2u);
    EXPECT_EQ(SlamBenchmark(options).runs().size(), 6u);
    options.logs = {"office", "intel"};
    EXPECT_EQ(SlamBenchmark(options).logs()[1].name, "intel");
    options.logs = {"fr079"};
    EXPECT_THROW(SlamBenchmark{options}, std::invalid_argument);
    options.logs = {"intel", "intel"};
    EXPECT_THROW(SlamBenchmark{options}, std::invalid_argument);
    options.logs = {};
    options.engines = {SlamEngine::Graph, SlamEngine::Graph};
    EXPECT_THROW(SlamBenchmark{options}, std::invalid_argument);
    options.engines = {};
    EXPECT_THROW(SlamBenchmark{options}, std::invalid_argument);
    EXPECT_EQ(engineFromName("icp-slam"), SlamEngine::IcpSlam);
    EXPECT_FALSE(engineFromName("cartographer"));
}

// ---- map picture --------------------------------------------------------------------------

TEST(MapComparisonImage, PanelsSideBySideAtOneScale) {
    TempDir dir;
    // 0.05 m cells, 200 x 100 px grey with a 100 x 50 px mapped part; and 0.10 m cells, a
    // 50 x 25 px mapped part: the same 5 m x 2.5 m, so both panels come out the same size.
    cv::Mat fine(100, 200, CV_8UC1, cv::Scalar(128));
    fine(cv::Rect(50, 25, 100, 50)).setTo(255);
    cv::Mat coarse(60, 60, CV_8UC1, cv::Scalar(128));
    coarse(cv::Rect(5, 5, 50, 25)).setTo(255);
    cv::imwrite(dir.file("fine.png"), fine);
    cv::imwrite(dir.file("coarse.png"), coarse);
    const std::string out = dir.file("maps.png");
    saveMapComparison({{"fine", dir.file("fine.png"), 0.05, 0, ""},
                       {"coarse", dir.file("coarse.png"), 0.10, 0, ""},
                       {"failed", "", 0.05, 0, "failed: exit status 1"}},
                      "heading", out);
    const cv::Mat image = cv::imread(out);
    ASSERT_FALSE(image.empty());
    // Each mapped part (100 x 50 px at 0.05 m) plus its 10 px border, and the grey box.
    EXPECT_GE(image.cols, 2 * 120 + 300);
    EXPECT_GE(image.rows, 70);
    EXPECT_THROW(saveMapComparison({{"x", dir.file("none.png"), 0.05, 0, ""}}, "h", out),
                 std::runtime_error);
    EXPECT_THROW(saveMapComparison({}, "h", out), std::invalid_argument);
}

TEST(MapComparisonImage, AlignmentBetweenTwoFramesOfOneTrajectory) {
    // The same path in a frame turned by 30 deg and moved by (1, 2): the alignment undoes it.
    const mrpt::math::TPose2D frame(1, 2, M_PI / 6);
    toposlam::io::Trajectory2D reference, moved;
    for (int i = 0; i < 20; ++i) {
        const mrpt::math::TPose2D p(0.3 * i, std::sin(0.5 * i), 0.1 * i);
        reference.push_back({100.0 + i, p});
        moved.push_back({100.0 + i, frame + p});
    }
    const mrpt::math::TPose2D back = alignmentTo(reference, moved, 1e-5);
    EXPECT_NEAR(back.phi, -M_PI / 6, 1e-9);
    const mrpt::math::TPose2D first = back + moved[5].pose;
    EXPECT_NEAR(first.x, reference[5].pose.x, 1e-9);
    EXPECT_NEAR(first.y, reference[5].pose.y, 1e-9);
    moved.resize(1);  // one stamp in common: nothing to align
    EXPECT_EQ(alignmentTo(reference, moved, 1e-5).phi, 0.0);
}

TEST(MapComparisonImage, TurnsPicturesBeforeCropping) {
    TempDir dir;
    cv::Mat bar(200, 200, CV_8UC1, cv::Scalar(128));
    bar(cv::Rect(50, 90, 100, 20)).setTo(255);  // 100 px wide, 20 px high
    cv::imwrite(dir.file("bar.png"), bar);
    const std::string out = dir.file("turned.png");
    saveMapComparison({{"t", dir.file("bar.png"), 0.05, 0.0, ""}}, "", out);
    const cv::Mat flat = cv::imread(out);
    saveMapComparison({{"t", dir.file("bar.png"), 0.05, M_PI / 2, ""}}, "", out);
    const cv::Mat upright = cv::imread(out);
    ASSERT_FALSE(flat.empty());
    ASSERT_FALSE(upright.empty());
    // Turned a quarter: the mapped part is 20 px wide and 100 px high (+ borders and titles).
    EXPECT_GT(flat.cols, 100);
    EXPECT_LT(upright.cols, 100);
    EXPECT_GT(upright.rows, flat.rows + 60);
}

// ---- report -------------------------------------------------------------------------------

TEST(SlamBenchmarkReport, RowsNotesAndJson) {
    SlamBenchmarkResult result;
    result.cores = 2;
    SlamBenchmarkLogResult log;
    log.log = {"office", "office.rawlog", "", "office_gt.txt", ""};
    log.scans = 368;
    log.durationSeconds = 270;
    log.relations = 4;
    SlamBenchmarkRow ok;
    ok.run.engine = SlamEngine::Graph;
    ok.run.status = SlamEngineRun::Status::Ok;
    ok.run.process.exitCode = 0;
    ok.run.process.wallSeconds = 2.7;
    ok.run.process.userCpuSeconds = 1.5;
    ok.run.process.peakRssBytes = 100u * 1024 * 1024;
    ok.run.summary = {{"loops", {{"accepted", 7}, {"rejected", 2}, {"withdrawn", 1}}}};
    const toposlam::io::Trajectory2D estimate = {{1, {0, 0, 0}}, {2, {1, 0, 0}}, {3, {2, 0, 0}}};
    const PoseRelations relations = {{1, 2, {1, 0, 0}}, {2, 3, {1.5, 0, 0}}, {1, 9, {0, 0, 0}}};
    ok.evaluation = evaluateMethod("graph", "office.rawlog", estimate, relations, &estimate, 1e-5);
    SlamBenchmarkRow skipped;
    skipped.run.engine = SlamEngine::IcpSlam;
    skipped.run.status = SlamEngineRun::Status::Skipped;
    skipped.run.note = "icp-slam is not installed";
    log.rows = {ok, skipped};
    result.logs.push_back(log);

    const std::string table = formatSlamBenchmarkTable(result);
    // Errors {0, 0.5} m: 0.25 ± 0.3536; 2 of 3 matched; 270 s log in 2.7 s wall, 1.5 s CPU.
    EXPECT_TRUE(contains(table, "| office | graph | 2 / 3 | 0.2500 ± 0.3536 | 0.000 ± 0.000 |"))
        << table;
    EXPECT_TRUE(contains(table, "| 2.7 | 1.5 | 100× / 180× | 100 | 7 / 2 / 1 |")) << table;
    EXPECT_TRUE(contains(table, "| office | icp-slam | not run [1] |")) << table;
    EXPECT_TRUE(contains(table, "[1] office icp-slam: icp-slam is not installed")) << table;
    EXPECT_TRUE(contains(table, "ATE RMSE / max (m)")) << table;
    EXPECT_FALSE(result.anyFailed());

    const nlohmann::json j = slamBenchmarkJson(result);
    const nlohmann::json& run = j["logs"][0]["runs"][0];
    EXPECT_EQ(run["engine"], "graph");
    EXPECT_EQ(run["status"], "ok");
    EXPECT_EQ(run["accuracy"]["relations_matched"], 2);
    EXPECT_DOUBLE_EQ(run["accuracy"]["translation_m"]["mean"].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(run["process"]["real_time_factor"].get<double>(), 100.0);
    EXPECT_DOUBLE_EQ(run["process"]["peak_rss_mib"].get<double>(), 100.0);
    EXPECT_EQ(run["summary"]["loops"]["accepted"], 7);
    EXPECT_TRUE(run["accuracy"].contains("ate"));
    // The evaluator's own JSON for the method, key for key (toposlam-eval-slam --json).
    EXPECT_EQ(run["accuracy"], nlohmann::json(evaluationJson(*log.rows[0].evaluation)));
    EXPECT_TRUE(run["accuracy"].contains("along_track"));
    EXPECT_TRUE(run["accuracy"].contains("by_turn"));
    EXPECT_EQ(j["logs"][0]["runs"][1]["status"], "skipped");

    result.logs[0].rows[1].run.status = SlamEngineRun::Status::Failed;
    EXPECT_TRUE(result.anyFailed());
    EXPECT_TRUE(contains(formatSlamBenchmarkTable(result), "| office | icp-slam | FAILED [1] |"));
}

// The logs of one robot (group), summed up per engine: ATE mean, median and worst over the
// scored logs; failed runs counted, not scored; logs without a group left out.
TEST(SlamBenchmarkReport, LogsOfARobotAreSummedUpPerEngine) {
    SlamBenchmarkResult result;
    const toposlam::io::Trajectory2D truth = {{1, {0, 0, 0}}, {2, {1, 0, 0}}, {3, {2, 0, 0}}};
    const PoseRelations relations = {{1, 2, {1, 0, 0}}, {2, 3, {1, 0, 0}}};
    // A log whose estimate is `truth` with its middle pose `offset` m off (the evaluator's ATE
    // grows with it); returns that ATE.
    const auto addLog = [&](const std::string& name, const std::string& group, double offset,
                            bool failed) {
        SlamBenchmarkLogResult log;
        log.log = {name, name + ".rawlog", "", name + "_gt.txt", group};
        SlamBenchmarkRow row;
        row.run.engine = SlamEngine::Graph;
        row.run.status = failed ? SlamEngineRun::Status::Failed : SlamEngineRun::Status::Ok;
        if (!failed) {
            toposlam::io::Trajectory2D estimate = truth;
            estimate[1].pose.y += offset;
            row.evaluation = evaluateMethod("graph", name, estimate, relations, &truth, 1e-5);
        }
        log.rows = {row};
        result.logs.push_back(log);
        return failed ? 0.0 : row.evaluation->absolute->position.rms;
    };
    addLog("office", "", 0.3, false);  // no group: not summed up
    const double a = addLog("plan.urg.seed1", "urg", 0.1, false);
    const double b = addLog("plan.lms.seed1", "lms", 0.05, false);
    const double c = addLog("plan.urg.seed2", "urg", 0.4, false);
    addLog("plan.urg.seed3", "urg", 0, true);
    const double d = addLog("plan.urg.seed4", "urg", 0.2, false);
    ASSERT_GT(a, 0);
    ASSERT_LT(a, d);
    ASSERT_LT(d, c);

    const std::vector<SlamGroupSummary> groups = summariseByGroup(result);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].group, "urg");  // in the order their first log ran
    EXPECT_EQ(groups[1].group, "lms");
    const SlamGroupSummary& urg = groups[0];
    EXPECT_EQ(urg.logs, 4u);
    EXPECT_EQ(urg.failed, 1u);
    EXPECT_EQ(urg.ate.count, 3u);
    EXPECT_NEAR(urg.ate.mean, (a + c + d) / 3, 1e-12);
    EXPECT_NEAR(urg.ateMedian, d, 1e-12);
    EXPECT_NEAR(urg.ate.max, c, 1e-12);
    EXPECT_EQ(urg.worstLog, "plan.urg.seed2");
    EXPECT_NEAR(groups[1].ate.mean, b, 1e-12);

    const std::string table = formatSlamBenchmarkTable(result);
    EXPECT_TRUE(contains(table, "| urg | graph | 3 / 4 |")) << table;
    EXPECT_TRUE(contains(table, ": plan.urg.seed2 |")) << table;
    EXPECT_EQ(slamBenchmarkJson(result)["by_robot"].size(), 2u);
    // Without groups, no such table.
    result.logs.resize(1);
    EXPECT_FALSE(contains(formatSlamBenchmarkTable(result), "by robot"));
    EXPECT_TRUE(slamBenchmarkJson(result)["by_robot"].empty());
}
