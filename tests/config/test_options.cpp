// config::Options on an example struct with every kind of field: strict loading (each kind of
// bad value, unknown keys with the nearest one named), save -> load round trip, validation.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/config/NearestName.h>
#include <toposlam/config/Options.h>

#include <OptionsContract.h>

#include <cmath>
#include <memory>
#include <sstream>

using toposlam::config::ConfigError;
using toposlam::config::Options;
using toposlam::config::OptionsSchema;

namespace {

enum class Fit { TwoPoint, LeastSquares };

struct Nested {
    double k = 15;
    bool enabled = true;
    void declare(OptionsSchema& s) {
        s.real("k", k, "", "scale").above(0);
        s.flag("enabled", enabled, "on or off");
    }
};

struct Example : Options {
    double range = 20;                  // m
    double fov = mrpt::DEG2RAD(270.0);  // rad
    float ratio = 0.25f;
    unsigned beams = 361;
    long offset = -3;
    std::size_t count = 7;
    bool paper = false;
    std::string label = "LASER";
    Fit fit = Fit::TwoPoint;
    double minRange = 0.05, maxRange = 30;
    double variance = 0.015 * 0.015;  // m^2, written as a std in m
    Nested jump;

    void declare(OptionsSchema& s) override {
        s.real("range", range, "m", "how far").above(0);
        s.angle("fov", fov, "first to last beam").above(0).atMost(360);
        s.real("ratio", ratio, "", "a float").within(0, 1);
        s.integer("beams", beams, "", "readings").within(2, 100000);
        s.integer("offset", offset, "", "signed");
        s.integer("count", count, "", "unsigned, any");
        s.flag("paper", paper, "as printed");
        s.text("label", label, "sensor label");
        s.choice("fit", fit, {{"two_point", Fit::TwoPoint}, {"least_squares", Fit::LeastSquares}},
                 "line fit");
        s.real("min_range", minRange, "m", "nearest").atLeast(0);
        s.real("max_range", maxRange, "m", "farthest").above(0);
        s.converted(
            "std", variance, [](double v) { return v * v; }, [](double v) { return std::sqrt(v); },
            "m", "standard deviation");
        s.group("jump_", jump);
        s.require([this] { return minRange < maxRange; }, "min_range", "must be below max_range");
    }
};

mrpt::config::CConfigFileMemory ini(const std::string& text) {
    mrpt::config::CConfigFileMemory c;
    c.setContent(text);
    return c;
}

/// The ConfigError message of loading `text` into defaults ("" when it loads).
std::string loadError(const std::string& text) {
    Example e;
    try {
        e.loadFromConfigFile(ini(text), "S");
    } catch (const ConfigError& error) {
        return error.what();
    }
    return "";
}

std::string saved(const Options& o) {
    mrpt::config::CConfigFileMemory c;
    o.saveToConfigFile(c, "S");
    return c.getContent();
}

}  // namespace

TEST(Options, LoadsEveryKindAndKeepsAbsentKeys) {
    Example e;
    e.loadFromConfigFile(ini("[S]\nrange = 5.5\nfov_deg = 180\nratio = 0.5\nbeams = 100\n"
                             "offset = -10\ncount = 3\npaper = true\nlabel = FLASER\n"
                             "fit = least_squares\nstd = 0.02\njump_k = 7\njump_enabled = off\n"),
                         "S");
    EXPECT_EQ(e.range, 5.5);
    EXPECT_EQ(e.fov, mrpt::DEG2RAD(180.0));
    EXPECT_EQ(e.ratio, 0.5f);
    EXPECT_EQ(e.beams, 100u);
    EXPECT_EQ(e.offset, -10);
    EXPECT_EQ(e.count, 3u);
    EXPECT_TRUE(e.paper);
    EXPECT_EQ(e.label, "FLASER");
    EXPECT_EQ(e.fit, Fit::LeastSquares);
    EXPECT_EQ(e.variance, 0.02 * 0.02);
    EXPECT_EQ(e.jump.k, 7);
    EXPECT_FALSE(e.jump.enabled);
    EXPECT_EQ(e.maxRange, 30);  // absent: unchanged

    Example untouched;
    untouched.loadFromConfigFile(ini("[Other]\nrange = 1\n"), "S");  // no [S]: nothing changes
    EXPECT_EQ(saved(untouched), saved(Example()));
}

TEST(Options, EveryBadValueIsAnErrorNamingSectionKeyAndValue) {
    EXPECT_EQ(loadError("[S]\nrange = abc\n"), "[S] range = abc: not a number");
    EXPECT_EQ(loadError("[S]\nrange = 5 m\n"), "[S] range = 5 m: not a number");
    EXPECT_EQ(loadError("[S]\nrange = nan\n"), "[S] range = nan: must be a finite number");
    EXPECT_EQ(loadError("[S]\nrange = -inf\n"), "[S] range = -inf: must be a finite number");
    EXPECT_EQ(loadError("[S]\nrange = 1e999\n"), "[S] range = 1e999: must be a finite number");
    EXPECT_EQ(loadError("[S]\nrange = -1\n"), "[S] range = -1: must be > 0");
    EXPECT_EQ(loadError("[S]\nrange = 0\n"), "[S] range = 0: must be > 0");
    EXPECT_EQ(loadError("[S]\nrange =\n"), "[S] range = : not a number");
    EXPECT_EQ(loadError("[S]\nfov_deg = 400\n"), "[S] fov_deg = 400: must be in (0, 360]");
    EXPECT_EQ(loadError("[S]\nratio = 1.5\n"), "[S] ratio = 1.5: must be in [0, 1]");
    EXPECT_EQ(loadError("[S]\nbeams = 2.5\n"), "[S] beams = 2.5: not a whole number");
    EXPECT_EQ(loadError("[S]\nbeams = 1\n"), "[S] beams = 1: must be in [2, 100000]");
    EXPECT_EQ(loadError("[S]\ncount = -1\n").rfind("[S] count = -1: must be in [0, ", 0), 0u);
    EXPECT_EQ(loadError("[S]\noffset = 99999999999999999999\n"),
              "[S] offset = 99999999999999999999: not a whole number");
    EXPECT_EQ(loadError("[S]\npaper = maybe\n"),
              "[S] paper = maybe: expected true or false (also 1/0, yes/no, on/off)");
    EXPECT_EQ(loadError("[S]\nfit = cubic\n"),
              "[S] fit = cubic: expected two_point or least_squares");
    EXPECT_EQ(loadError("[S]\njump_k = 0\n"), "[S] jump_k = 0: must be > 0");
    EXPECT_EQ(loadError("[S]\nlabel =\n"), "[S] label = : must not be empty");
}

TEST(Options, UnknownKeysNameTheNearestKnownKey) {
    EXPECT_EQ(loadError("[S]\nbeam = 3\n"), "[S] beam = 3: unknown key; did you mean 'beams'?");
    EXPECT_EQ(loadError("[S]\nfov = 90\n"), "[S] fov = 90: unknown key; did you mean 'fov_deg'?");
    EXPECT_EQ(loadError("[S]\nBeams = 3\n"), "[S] Beams = 3: unknown key; did you mean 'beams'?");
    EXPECT_EQ(loadError("[S]\njump_kk = 3\n"),
              "[S] jump_kk = 3: unknown key; did you mean 'jump_k'?");
    EXPECT_EQ(toposlam::config::nearestName("min_rang", Example().keys()), "min_range");
}

TEST(Options, RulesAreCheckedAndABadFileChangesNothing) {
    EXPECT_EQ(loadError("[S]\nmin_range = 40\n"), "[S] min_range = 40: must be below max_range");
    Example e;
    EXPECT_THROW(e.loadFromConfigFile(ini("[S]\nrange = 3\nmax_range = 0.01\n"), "S"), ConfigError);
    EXPECT_THROW(e.loadFromConfigFile(ini("[S]\nrange = 3\nbeams = x\n"), "S"), ConfigError);
    EXPECT_EQ(saved(e), saved(Example()));
}

TEST(Options, SaveWritesEveryFieldAndReadsBackTheSame) {
    const Example defaults;
    const std::string text = saved(defaults);
    for (const std::string& key : defaults.keys())
        EXPECT_NE(text.find(key + " "), std::string::npos) << key << " not written:\n" << text;
    EXPECT_NE(text.find("fov_deg"), std::string::npos);
    EXPECT_NE(text.find("how far [m; > 0]"), std::string::npos) << text;
    Example loaded;
    loaded.range = 1;
    loaded.fov = 1;
    loaded.variance = 1;
    loaded.loadFromConfigFile(ini(text), "S");
    EXPECT_EQ(saved(loaded), text);
    EXPECT_EQ(loaded.fov, defaults.fov);  // 270 deg -> rad -> "270" -> the same double
    EXPECT_EQ(loaded.variance, defaults.variance);

    // dumpToTextStream: a section body that loads back the same.
    std::ostringstream dump;
    defaults.dumpToTextStream(dump);
    Example fromDump;
    fromDump.range = 2;
    fromDump.loadFromConfigFile(ini("[S]\n" + dump.str()), "S");
    EXPECT_EQ(saved(fromDump), text);
    EXPECT_NE(dump.str().find("# how far [m; > 0]\nrange = 20\n"), std::string::npos) << dump.str();
}

TEST(Options, ValidateChecksValuesSetInCode) {
    Example e;
    EXPECT_NO_THROW(e.validate("S"));
    e.range = std::nan("");
    try {
        e.validate("S");
        FAIL() << "NaN accepted";
    } catch (const ConfigError& error) {
        EXPECT_EQ(std::string(error.what()), "[S] range = nan: must be a finite number");
        EXPECT_EQ(error.key(), "range");
    }
    e.range = 1;
    e.beams = 1;
    EXPECT_THROW(e.validate("S"), ConfigError);
    e.beams = 10;
    e.minRange = 50;
    EXPECT_THROW(e.validate("S"), ConfigError);
}

TEST(Options, TheGenericContractHoldsForTheExample) {
    toposlam::test::expectOptionsContract([] { return std::make_unique<Example>(); }, "S");
}

TEST(Options, NumbersAreWrittenShortAndExact) {
    struct Numbers : Options {
        double a = 0.1, b = 1e-6, c = 1e-5, d = 123456.5, e = M_PI / 3, f = 0.35;
        void declare(OptionsSchema& s) override {
            s.real("a", a, "", "a");
            s.real("b", b, "", "b");
            s.angle("c", c, "c");
            s.real("d", d, "", "d");
            s.angle("e", e, "e");
            s.angle("f", f, "f");
        }
    } n;
    std::ostringstream dump;
    n.dumpToTextStream(dump);
    EXPECT_NE(dump.str().find("a = 0.1\n"), std::string::npos) << dump.str();
    EXPECT_NE(dump.str().find("b = 1e-06\n"), std::string::npos) << dump.str();
    EXPECT_NE(dump.str().find("d = 123456.5\n"), std::string::npos) << dump.str();
    Numbers back;
    back.a = back.b = back.c = back.d = back.e = back.f = 0;
    back.loadFromConfigFile(ini("[S]\n" + dump.str()), "S");
    EXPECT_EQ(back.a, n.a);
    EXPECT_EQ(back.b, n.b);
    EXPECT_EQ(back.c, n.c);
    EXPECT_EQ(back.d, n.d);
    EXPECT_EQ(back.e, n.e);
    EXPECT_EQ(back.f, n.f);
}
