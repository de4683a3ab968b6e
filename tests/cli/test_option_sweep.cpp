// Every app x every numeric option x {just below its range, just above it, NaN, a fraction
// for a count}: a clear "error: --option: ..." naming the option, exit status 2 (bad usage),
// and nothing written to the output folder. How each kind of text is read ("inf", "12abc",
// "1e999", ...) is cli::NumberRange's, tested in process (test_number_range.cpp); each app
// shows it reports every kind on its first option. Unknown options are bad usage too. To cover
// a new option, add a row to kNumericOptions.
#include <TestSupport.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using toposlam::test::runApp;
using toposlam::test::TempDir;

namespace {

struct NumericOption {
    const char* app;
    const char* option;  ///< as written on the command line
    double min, max;     ///< what it accepts: [min, max], or (min, max] when minExcluded
    bool minExcluded;
    bool integer;
};

constexpr double kBig = 1e6;
// The accepted ranges, as each app's --help states them.
const NumericOption kNumericOptions[] = {
    {"toposlam-annotate-features", "--carmen-max-range", 0, 1000, true, false},
    {"toposlam-annotate-features", "--max-scans", 0, 1e9, false, true},
    {"toposlam-bench-features", "--rooms", 1, 100000, false, true},
    {"toposlam-bench-features", "--seed", 0, 2147483647, false, true},
    {"toposlam-bench-features", "--real-scans", 0, 1e9, false, true},
    {"toposlam-bench-features", "--repetitions", 1, 1000, false, true},
    {"toposlam-bench-features", "--min-time", 0, 60, true, false},
    {"toposlam-bench-matching", "--sim-pairs", 0, 100000, false, true},
    {"toposlam-bench-matching", "--max-real-pairs", 0, 1e9, false, true},
    {"toposlam-bench-planning", "--free-threshold", 0.5, 0.999, false, false},
    {"toposlam-bench-planning", "--pairs", 0, kBig, false, true},
    {"toposlam-bench-planning", "--robot-radius", 0, 10, true, false},
    {"toposlam-bench-planning", "--time", 0, 3600, true, false},
    {"toposlam-bench-planning", "--attempts", 1, 1000, false, true},
    {"toposlam-bench-rooms", "--repeats", 1, 1000, false, true},
    {"toposlam-bench-rooms", "--cell-size", 0, 5, false, false},
    {"toposlam-bench-slam", "--timeout", 0, 1e6, false, false},
    {"toposlam-bench-slam", "--keep-every", 1, 1000, false, true},
    {"toposlam-bench-slam", "--keep-beam-every", 1, 1000, false, true},
    {"toposlam-bench-slam", "--clip-range", 0, 1000, false, false},
    {"toposlam-convert", "--carmen-max-range", 0, 1000, true, false},
    {"toposlam-convert", "--max-scans", 0, 1e9, false, true},
    {"toposlam-convert", "--keep-every", 1, 1000, false, true},
    {"toposlam-convert", "--keep-beam-every", 1, 1000, false, true},
    {"toposlam-convert", "--clip-range", 0, 1000, false, false},
    {"toposlam-convert", "--resolution", 0, 100, true, false},
    {"toposlam-eval-slam", "--frame-offset", -10, 10, false, false},
    {"toposlam-eval-slam", "--gt-separation", 0, kBig, false, false},
    {"toposlam-eval-slam", "--stamp-tolerance", 0, 3600, false, false},
    {"toposlam-eval-slam", "--worst", 0, 1e6, false, true},
    {"toposlam-plan", "--robot-radius", 0, 10, true, false},
    {"toposlam-plan", "--time", 0, 3600, true, false},
    {"toposlam-plan", "--free-threshold", 0.5, 0.999, false, false},
    {"toposlam-plan", "--attempts", 1, 1000, false, true},
    {"toposlam-plan", "--seed", 1, 2147483647, false, true},
    {"toposlam-rooms", "--door-width", 0, 10, true, false},
    {"toposlam-rooms", "--door-tolerance", 0, 10, false, false},
    {"toposlam-rooms", "--min-room-area", 0, 10000, false, false},
    {"toposlam-rooms", "--free-threshold", 0.5, 0.999, false, false},
    {"toposlam-rooms", "--resolution", 0, 100, true, false},
    {"toposlam-rooms", "--scale", 1, 8, false, true},
    {"toposlam-sim", "--beams", 2, 100000, false, true},
    {"toposlam-sim", "--fov-deg", 0, 360, true, false},
    {"toposlam-sim", "--max-range", 0, 1000, true, false},
    {"toposlam-sim", "--range-noise", 0, 10, false, false},
    {"toposlam-sim", "--bearing-noise-deg", 0, 45, false, false},
    {"toposlam-sim", "--people", 0, 1000, false, true},
    {"toposlam-sim", "--seed", 0, 2147483647, false, true},
    {"toposlam-sim", "--resolution", 0, 100, true, false},
};

// Options holding several numbers ("x,y"), with values each must refuse.
struct ListOption {
    const char* app;
    const char* option;
    std::vector<const char*> bad;
};
const ListOption kListOptions[] = {
    {"toposlam-rooms", "--origin", {"1", "1,2,3", "nan,0", "0,inf", "a,b", "1e300,0"}},
    {"toposlam-sim", "--origin", {"1", "nan,0", "0,1e300", "x,y"}},
    {"toposlam-sim", "--start", {"1", "1,2,3,4", "nan,1", "1,2,inf", "a,b"}},
    {"toposlam-convert", "--laser-offset", {"1,2", "0,0,nan", "a,b,c"}},
    {"toposlam-annotate-features", "--odometry-noise", {"1,2", "0,0,0,0,0,nan", "-1,0,0,0,0,0"}},
};

// A command line each app would accept apart from the option under test, writing only under
// `out`.
std::string validArguments(const std::string& app, const std::string& out) {
    const std::string office = toposlam::test::shareDir() + "/office/";
    const std::string map = "'" + office + "office.gridmap.gz'";
    const std::string log = "'" + office + "office.rawlog'";
    const std::string gt = "'" + office + "office_gt.txt'";
    const std::string o = "'" + out + "/";
    if (app == "toposlam-annotate-features")
        return log + " -o " + o + "a.rawlog' -q";
    if (app == "toposlam-bench-features")
        return "--no-real --json " + o + "b1.json'";
    if (app == "toposlam-bench-matching")
        return "-j " + o + "b2.json'";
    if (app == "toposlam-bench-planning")
        return "--json " + o + "b5.json'";
    if (app == "toposlam-bench-rooms")
        return "-o " + o + "b4.json'";
    if (app == "toposlam-bench-slam")
        return "--logs office --json " + o + "b3.json' --images " + o + "img'";
    if (app == "toposlam-convert")
        return log + " -o " + o + "c.rawlog' -q";
    if (app == "toposlam-eval-slam")
        return gt + " --ground-truth " + gt + " --json " + o + "e.json'";
    if (app == "toposlam-plan")
        return map + " " + o + "rooms.json' --from 1 --to 2 -o " + o + "plan'";
    if (app == "toposlam-rooms")
        return map + " -o " + o + "rooms' -q";
    if (app == "toposlam-sim")
        return map + " --tour -o " + o + "s.rawlog' -q";
    if (app == "toposlam-slam")
        return "'" + toposlam::test::configIni("toposlam-slam.ini") + "' " + log + " -o " + o +
               "slam'";
    ADD_FAILURE() << "no arguments for " << app;
    return "";
}

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The values `o` must refuse at its bounds: the nearest number outside each end, NaN, and a
// fraction when it counts.
std::vector<std::string> boundaryValues(const NumericOption& o) {
    std::vector<std::string> bad = {"nan"};
    if (o.minExcluded)
        bad.push_back(number(o.min));
    else
        bad.push_back(
            number(o.integer ? o.min - 1 : o.min - std::max(std::abs(o.min), 1.0) * 1e-9));
    bad.push_back(number(o.integer ? o.max + 1 : o.max * 1.01));
    if (o.integer)
        bad.push_back("1.5");
    return bad;
}

// Text that is no number in any range, or none the option's type can hold.
std::vector<std::string> formatValues(const NumericOption& o) {
    std::vector<std::string> bad = {"inf", "abc", "", "1e999", "12abc", "1e300"};
    if (o.integer)
        bad.push_back("18446744073709551615");
    return bad;
}

bool isEmptyDirectory(const std::string& dir) {
    return std::filesystem::is_empty(dir);
}

void expectBadUsage(const std::string& app, const std::string& option, const std::string& args) {
    TempDir dir;
    const auto r = runApp(app, validArguments(app, dir.path()) + " " + args);
    EXPECT_EQ(r.exitCode, 2) << app << " " << args << "\n" << r.output;
    EXPECT_NE(r.output.find("error: " + option + ": "), std::string::npos)
        << app << " " << args << ": the message names the option\n"
        << r.output;
    EXPECT_TRUE(isEmptyDirectory(dir.path())) << app << " " << args << " left a file behind";
}

class EveryApp : public testing::TestWithParam<std::string> {};

TEST_P(EveryApp, RefusesEveryOutOfRangeNumber) {
    const std::string app = GetParam();
    bool first = true;
    for (const NumericOption& o : kNumericOptions) {
        if (o.app != app)
            continue;
        std::vector<std::string> values = boundaryValues(o);
        if (first) {
            const std::vector<std::string> format = formatValues(o);
            values.insert(values.end(), format.begin(), format.end());
            first = false;
        }
        for (const std::string& value : values)
            expectBadUsage(app, o.option, std::string(o.option) + " '" + value + "'");
    }
    for (const ListOption& o : kListOptions) {
        if (o.app != app)
            continue;
        for (const char* value : o.bad)
            expectBadUsage(app, o.option, std::string(o.option) + " '" + value + "'");
    }
}

TEST_P(EveryApp, UnknownOptionsAreBadUsage) {
    expectBadUsage(GetParam(), "--no-such-option", "--no-such-option");
}

TEST_P(EveryApp, AnOptionWrittenWithAnEqualsSignSaysHowToWriteIt) {
    // TCLAP takes "--seed=3" for an option named "seed=3", or for a positional argument's
    // value and then misses a required one; the error says to write "--seed 3". Each app's
    // first numeric option; an unknown one with "=" stays an unknown option.
    const std::string app = GetParam();
    for (const NumericOption& o : kNumericOptions) {
        if (o.app != app || std::string(o.option).compare(0, 2, "--") != 0)
            continue;
        const auto r = runApp(app, std::string(o.option) + "=3");
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("options take their value after a space: write '" +
                                std::string(o.option) + " 3'"),
                  std::string::npos)
            << r.output;
        break;
    }
    const auto unknown = runApp(app, "--no-such-option=3");
    EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
    EXPECT_EQ(unknown.output.find("after a space"), std::string::npos) << unknown.output;
}

TEST_P(EveryApp, HelpShowsTheRangesAndTheTableHasEveryNumericOption) {
    const std::string app = GetParam();
    const auto r = runApp(app, "--help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::size_t rows = 0;
    for (const NumericOption& o : kNumericOptions) {
        if (o.app == app) {
            ++rows;
            EXPECT_NE(r.output.find(o.option), std::string::npos) << app << " " << o.option;
        }
    }
    // Every cli::NumberArg appends "Range: ..." to its help (TCLAP may wrap after the colon):
    // one row of kNumericOptions each, so an option added without a row fails here.
    std::size_t ranges = 0;
    for (std::size_t at = r.output.find("Range:"); at != std::string::npos;
         at = r.output.find("Range:", at + 1)) {
        ++ranges;
    }
    EXPECT_EQ(ranges, rows) << app << ": numeric options in --help vs rows in kNumericOptions";
}

INSTANTIATE_TEST_SUITE_P(Apps, EveryApp,
                         testing::Values("toposlam-annotate-features", "toposlam-bench-features",
                                         "toposlam-bench-matching", "toposlam-bench-planning",
                                         "toposlam-bench-rooms", "toposlam-bench-slam",
                                         "toposlam-convert", "toposlam-eval-slam", "toposlam-plan",
                                         "toposlam-rooms", "toposlam-sim", "toposlam-slam"),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(9);  // after "toposlam-"
                             for (char& c : name)
                                 c = c == '-' ? '_' : c;
                             return name;
                         });

}  // namespace
