// Every input fuzzing found to crash, hang or exhaust memory (tests/fuzz/findings/, see
// tests/fuzz/findings/README.md) run through the real app that reads it: exit status 1, a
// clear "error: <file>: ..." message, within 10 s, under 1 GB of memory, no output file.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "TestSupport.h"

namespace fs = std::filesystem;

namespace {

constexpr double kMaxSeconds = 10;
constexpr long kMaxRssKiB = 1024 * 1024;  // 1 GiB

struct BoundedRun {
    int exitCode = -1;  // -1: killed or crashed
    std::string output;
    double seconds = 0;
    long maxRssKiB = 0;
    bool timedOut = false;
};

// Runs bin/<app> <args> with its output in a file; kills it after 2 x kMaxSeconds so a hang
// fails the test instead of stalling the suite. The peak RSS is the app's own (exec'd by
// the shell).
BoundedRun runBounded(const std::string& app, const std::string& args, const std::string& log) {
    const std::string command =
        "exec '" + toposlam::test::binDir() + "/" + app + "' " + args + " >'" + log + "' 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    BoundedRun run;
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
        run.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (run.seconds > 2 * kMaxSeconds && !run.timedOut) {
            run.timedOut = true;
            ::kill(pid, SIGKILL);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.maxRssKiB = usage.ru_maxrss;
    std::ifstream in(log);
    run.output.assign(std::istreambuf_iterator<char>(in), {});
    return run;
}

std::string finding(const std::string& name) {
    return toposlam::test::shareDir() + "/../tests/fuzz/findings/" + name;
}

struct Finding {
    const char* file;
    const char* app;
    const char* args;  // after the input; "OUT" is replaced by the output path
    const char* output;
};

// The app that reads each kind of file, and what it would write.
const Finding kFindings[] = {
    {"flaser_wrap5.clf", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"robotlaser_wrap.clf", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"rawlog_crash.rawlog", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"oom-4b998fc9.rawlog", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"oom-00091269.rawlog", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"null-observation.rawlog", "toposlam-convert", "-o OUT", "out.rawlog"},
    {"oom-8df72e38.gridmap", "toposlam-convert", "-o OUT", "out.yaml"},
    {"hang-pct86.yaml", "toposlam-convert", "-o OUT", "out.gridmap.gz"},
    {"deep_nesting_32k.json", "toposlam-plan", "--from 1 --to 2 -o OUT", "plan"},
    {"json_bad_u_escape.json", "toposlam-plan", "--from 1 --to 2 -o OUT", "plan"},
};

// Test names and failure messages show the file, not the struct's bytes.
void PrintTo(const Finding& f, std::ostream* os) {
    *os << f.file;
}

class FuzzFinding : public testing::TestWithParam<Finding> {};

std::string nameOf(const testing::TestParamInfo<Finding>& info) {
    std::string name = info.param.file;
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    }
    return name;
}

TEST_P(FuzzFinding, EndsWithAClearErrorQuicklyInBoundedMemory) {
    const Finding& f = GetParam();
    toposlam::test::TempDir dir;
    // The input is copied so that its path in the message is known and nothing else sees it.
    const std::string input = dir.file(f.file);
    fs::copy_file(finding(f.file), input);
    std::string args = f.args;
    const std::string output = dir.file(f.output);
    args.replace(args.find("OUT"), 3, "'" + output + "'");
    // toposlam-plan reads the map the rooms were segmented from first.
    const std::string prefix =
        std::string(f.app) == "toposlam-plan"
            ? "'" + toposlam::test::shareDir() + "/office/office.gridmap.gz' "
            : "";
    const BoundedRun run = runBounded(f.app, prefix + "'" + input + "' " + args, dir.file("log"));

    EXPECT_FALSE(run.timedOut) << f.file << ": killed after " << run.seconds << " s";
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("error: " + input + ": "), std::string::npos) << run.output;
    EXPECT_LT(run.seconds, kMaxSeconds);
    EXPECT_LT(run.maxRssKiB, kMaxRssKiB) << "peak RSS " << run.maxRssKiB << " KiB";
    EXPECT_FALSE(fs::exists(output)) << output << " was written";
    for (const auto& entry : fs::directory_iterator(dir.path())) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == f.file || name == "log") << "left behind: " << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Findings, FuzzFinding, testing::ValuesIn(kFindings), nameOf);

}  // namespace
