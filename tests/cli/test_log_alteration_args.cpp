// cli::LogAlterationArgs: the five log alteration options shared by toposlam-convert and
// toposlam-bench-slam.
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/LogAlterationArgs.h>

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

using namespace toposlam;

namespace {

struct Parsed {
    std::optional<int> status;
    io::LogAlteration alteration;
    std::vector<std::string> given;
    std::string help;
};

Parsed parse(std::vector<std::string> args) {
    TCLAP::CmdLine cmd("test", ' ', "1");
    const cli::LogAlterationArgs options(cmd,
                                         {"Scan note.", "", "", "Odometry note.", "Mirror note."});
    args.insert(args.begin(), "app");
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());
    Parsed out;
    out.status = cli::parseCommandLine(cmd, static_cast<int>(argv.size()), argv.data());
    out.alteration = options.alteration();
    out.given = options.given();
    for (const TCLAP::Arg* arg : cmd.getArgList())
        out.help += arg->getDescription() + "\n";
    return out;
}

}  // namespace

TEST(LogAlterationArgs, GivesTheAlterationAndTheOptionsGiven) {
    const Parsed none = parse({});
    EXPECT_EQ(none.status, std::nullopt);
    EXPECT_FALSE(none.alteration.any());
    EXPECT_TRUE(none.given.empty());

    const Parsed all = parse({"--keep-every", "3", "--keep-beam-every", "2", "--clip-range", "5.6",
                              "--no-odometry", "--mirror"});
    ASSERT_EQ(all.status, std::nullopt);
    EXPECT_EQ(all.alteration.keepEvery, 3u);
    EXPECT_EQ(all.alteration.keepBeamEvery, 2u);
    EXPECT_EQ(all.alteration.clipRange, 5.6);
    EXPECT_TRUE(all.alteration.dropOdometry);
    EXPECT_TRUE(all.alteration.mirror);
    EXPECT_EQ(all.given, (std::vector<std::string>{"--keep-every", "--keep-beam-every",
                                                   "--clip-range", "--no-odometry", "--mirror"}));
    // The app's notes follow the common text of their option.
    EXPECT_NE(all.help.find("lower scan rate would have recorded it; the odometry is the pose "
                            "at each kept scan. Scan note. Default: 1 = every scan."),
              std::string::npos)
        << all.help;
    EXPECT_NE(all.help.find("(a laser-only log). Odometry note."), std::string::npos) << all.help;
    EXPECT_NE(all.help.find("which way the robot turns. Mirror note."), std::string::npos)
        << all.help;

    const Parsed one = parse({"--clip-range", "8"});
    EXPECT_EQ(one.given, std::vector<std::string>{"--clip-range"});
    EXPECT_TRUE(one.alteration.any());
    EXPECT_FALSE(one.alteration.mirror);
    EXPECT_TRUE(parse({"--mirror"}).alteration.any());

    testing::internal::CaptureStderr();
    EXPECT_EQ(parse({"--keep-every", "0"}).status, cli::kBadUsage);
    EXPECT_EQ(parse({"--clip-range", "-1"}).status, cli::kBadUsage);
    testing::internal::GetCapturedStderr();
}
