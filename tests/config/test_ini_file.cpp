// openIniFile(): a file that is not an .ini file at all is an error naming the file and line;
// errors of values read from a real file name the file.
#include <gtest/gtest.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/config/IniFile.h>
#include <toposlam/config/Options.h>

#include <fstream>

#include "TestSupport.h"

using toposlam::config::ConfigError;
using toposlam::config::openIniFile;

namespace {

struct Small : toposlam::config::Options {
    double range = 20;
    void declare(toposlam::config::OptionsSchema& s) override {
        s.real("max_range", range, "m", "farthest").above(0);
    }
};

std::string write(const toposlam::test::TempDir& dir, const std::string& text) {
    const std::string path = dir.file("f.ini");
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/// The message of opening (and loading [S] of) a file with `text`; "" when it loads.
std::string openError(const std::string& text) {
    toposlam::test::TempDir dir;
    const std::string path = write(dir, text);
    try {
        auto ini = openIniFile(path);
        Small().loadFromConfigFile(*ini, "S");
    } catch (const ConfigError& e) {
        std::string m = e.what();
        EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
        return m.substr(path.size() + 2);
    }
    return "";
}

}  // namespace

TEST(IniFile, AcceptsCommentsSectionsAndKeys) {
    EXPECT_EQ(openError("# comment\n; comment\n// comment\n\n[S]\n  max_range = 5  \r\n"), "");
    EXPECT_EQ(openError(""), "");
}

TEST(IniFile, RefusesWhatIsNoIniFile) {
    EXPECT_EQ(openError("[S]\nmax_range 5\n"),
              "line 2: expected 'key = value', '[section]' or a # comment");
    EXPECT_EQ(openError("max_range = 5\n"), "line 1: 'max_range' comes before any [section]");
    EXPECT_EQ(openError("[S\n"),
              "line 1: expected [section] with a name of letters, digits, _ . -");
    EXPECT_EQ(openError("[S]\nmax_range = 1\nmax_range = 2\n"),
              "line 3: [S] max_range is set again (first on line 2)");
    EXPECT_EQ(openError(std::string("[S]\nmax_range = 1\x01\n")),
              "line 2: control character (byte 1): not a text file");
    EXPECT_EQ(openError(std::string("[S]\nmax_range = \xff\xfe\n")), "line 2: not UTF-8 text");
    EXPECT_EQ(openError(std::string("\x7f\x45LF\x02\x01\x01\0\0\0", 10)),
              "line 1: control character (byte 2): not a text file");
}

TEST(IniFile, ValueErrorsNameTheFile) {
    EXPECT_EQ(openError("[S]\nmax_range = abc\n"), "[S] max_range = abc: not a number");
    EXPECT_EQ(openError("[S]\nmax_rnge = 3\n"),
              "[S] max_rnge = 3: unknown key; did you mean 'max_range'?");
    EXPECT_EQ(openError("[S]\nmax_range = 3  # m\n"),
              "[S] max_range = 3  # m: not a number (comments go on a line of their own)");
}

TEST(IniFile, MissingFilesAndSections) {
    try {
        openIniFile("/nonexistent/x.ini");
        FAIL();
    } catch (const ConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/x.ini: no such file");
    }
    toposlam::test::TempDir dir;
    const std::string path = write(dir, "[Laser]\nbeams = 3\n[Odometry]\n");
    auto ini = openIniFile(path);
    EXPECT_NO_THROW(toposlam::config::requireSection(*ini, "Laser"));
    try {
        toposlam::config::requireSection(*ini, "Lazer");
        FAIL();
    } catch (const ConfigError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": [Lazer]: no such section in the file; did you mean [Laser]?");
    }
    EXPECT_NO_THROW(toposlam::config::requireKnownSections(*ini, {"Laser", "Odometry", "People"}));
    EXPECT_THROW(toposlam::config::requireKnownSections(*ini, {"Laser", "People"}), ConfigError);
}

TEST(IniFile, NumbersWrittenForAnotherLibraryAreReadAsWritten) {
    toposlam::test::TempDir dir;
    const std::string path =
        write(dir,
              "[ICP]\nmaxIterations = -5\nthresholdDist = abc\nALFA = nan\nepsilon = 1e-6\n"
              "decimation = 2   # comment\nsmallest = 0.05\t; comment\nslack = 3 // comment\n"
              "glued = 4#5\n");
    const auto ini = openIniFile(path);
    using toposlam::config::readWrittenNumber;
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "maxIterations")->value, -5.0);
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "epsilon")->value, 1e-6);
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "epsilon")->text, "1e-6");  // as written
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "absent"), std::nullopt);
    // Comments after the number, as in MRPT's own ini files.
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "decimation")->value, 2.0);
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "smallest")->value, 0.05);
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "slack")->value, 3.0);
    EXPECT_EQ(readWrittenNumber(*ini, "ICP", "slack")->text, "3");
    EXPECT_EQ(
        toposlam::test::errorOf<ConfigError>([&] { readWrittenNumber(*ini, "ICP", "glued"); }),
        path + ": [ICP] glued = 4#5: not a number (comments go on a line of their own)");
    EXPECT_EQ(toposlam::test::errorOf<ConfigError>(
                  [&] { readWrittenNumber(*ini, "ICP", "thresholdDist"); }),
              path + ": [ICP] thresholdDist = abc: not a number");
    EXPECT_EQ(toposlam::test::errorOf<ConfigError>([&] { readWrittenNumber(*ini, "ICP", "ALFA"); }),
              path + ": [ICP] ALFA = nan: must be a finite number");
}
