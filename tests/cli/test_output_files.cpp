// cli::requireOutputsOfTheirOwn and cli::requireExtension: an app refuses, as bad usage, an
// output that would replace one of its inputs or another of its outputs, and an output whose
// name says another kind of file.
#include <toposlam/cli/CommandLine.h>

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace toposlam::cli;
namespace fs = std::filesystem;

namespace {

std::string usageError(const std::vector<FileArgument>& inputs,
                       const std::vector<FileArgument>& outputs) {
    return toposlam::test::errorOf<UsageError>([&] { requireOutputsOfTheirOwn(inputs, outputs); });
}

}  // namespace

TEST(OutputFiles, AnOutputOverAnInputIsBadUsage) {
    toposlam::test::TempDir dir;
    const std::string log = dir.file("a.clf");
    std::ofstream(log) << "FLASER ...";
    // The same file however it is named: as given, through "..", through a link.
    EXPECT_EQ(
        usageError({{"", log}}, {{"-o", log}}),
        "-o '" + log + "': the same file as the input '" + log + "' (it would be overwritten)");
    EXPECT_NE(usageError({{"", log}}, {{"-o", dir.file("sub/../a.clf")}}), "");
    fs::create_symlink(log, dir.file("link.clf"));
    EXPECT_NE(usageError({{"", dir.file("link.clf")}}, {{"-o", log}}), "");
    // Another file, an output not given, an input not given: fine.
    EXPECT_EQ(usageError({{"", log}}, {{"-o", dir.file("a.rawlog")}, {"--plot", ""}}), "");
    EXPECT_EQ(usageError({{"--poses", ""}}, {{"-o", dir.file("a.rawlog")}}), "");
}

TEST(OutputFiles, TwoOutputsOnOneFileAreBadUsage) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("o.json");  // not there yet
    EXPECT_EQ(usageError({}, {{"--json", out}, {"--write-relations", out}}),
              "--write-relations '" + out + "': the same file as the output --json '" + out + "'");
    EXPECT_EQ(usageError({}, {{"--json", out}, {"--write-relations", dir.file("r.txt")}}), "");
}

TEST(OutputFiles, ExtensionsAreRequiredCaseInsensitively) {
    EXPECT_NO_THROW(requireExtension({"-o", "log.rawlog"}, {".rawlog", ".rawlog.gz"}));
    EXPECT_NO_THROW(requireExtension({"-o", "LOG.RAWLOG.GZ"}, {".rawlog", ".rawlog.gz"}));
    EXPECT_NO_THROW(requireExtension({"--plot", ""}, {".png"}));  // not given
    try {
        requireExtension({"-o", "map.png"}, {".rawlog", ".rawlog.gz"});
        ADD_FAILURE() << "accepted";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "-o 'map.png': must end in .rawlog or .rawlog.gz");
    }
    EXPECT_THROW(requireExtension({"--plot", ".png"}, {".png"}), UsageError);  // no name
}

TEST(OutputFiles, TheOutputFolderIsCheckedBeforeTheWork) {
    toposlam::test::TempDir dir;
    EXPECT_NO_THROW(requireWritableOutputFolder({"-o", dir.file("a/b")}));
    EXPECT_FALSE(fs::exists(dir.file("a"))) << "nothing is created";
    EXPECT_NO_THROW(requireWritableOutputFolder({"-o", dir.path()}));  // already there
    std::ofstream(dir.file("file")) << "x";
    try {
        requireWritableOutputFolder({"-o", dir.file("file/out")});
        ADD_FAILURE() << "a folder under a file was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(dir.file("file/out") + ": cannot create the output"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(requireWritableOutputFolder({"-o", dir.file("file")}), std::runtime_error);
    EXPECT_THROW(requireWritableOutputFolder({"-o", ""}), UsageError);
}
