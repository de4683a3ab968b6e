#include <gtest/gtest.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "TestSupport.h"

using toposlam::io::InputError;
using toposlam::io::loadTrajectory;
using toposlam::io::saveTrajectory;
using toposlam::io::Trajectory2D;

namespace {

using toposlam::test::writeText;

// The InputError message of loading `path`, or "" if it loads.
std::string trajectoryLoadError(const std::string& path) {
    return toposlam::test::errorOf<InputError>([&] { loadTrajectory(path); });
}

}  // namespace

TEST(Trajectory, RoundTripIsExact) {
    toposlam::test::TempDir dir;
    Trajectory2D t;
    // CARMEN ipc stamps (6 decimals at 1e9 s), MRPT stamps (100 ns ticks) and awkward values.
    t.push_back({976052857.337284, {0.0, 0.0, -0.002458}});
    t.push_back({1134864629.8951823, {576.536523, 0.106594, -2.255213}});
    t.push_back({1211.520329, {-3.034287, 8.291214, -3.120965}});
    t.push_back({0.1 + 0.2, {1.0 / 3.0, -std::numeric_limits<double>::min(), M_PI}});
    saveTrajectory(t, dir.file("t.txt"));
    const Trajectory2D back = loadTrajectory(dir.file("t.txt"));
    ASSERT_EQ(back.size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_EQ(back[i].stamp, t[i].stamp) << i;  // bit-exact, not approximately
        EXPECT_EQ(back[i].pose.x, t[i].pose.x) << i;
        EXPECT_EQ(back[i].pose.y, t[i].pose.y) << i;
        EXPECT_EQ(back[i].pose.phi, t[i].pose.phi) << i;
    }
    // CARMEN stamps keep their printed digits (what relation files are matched against).
    std::ifstream in(dir.file("t.txt"));
    std::string header, first;
    std::getline(in, header);
    std::getline(in, first);
    EXPECT_EQ(header, "# timestamp x y yaw");
    EXPECT_EQ(first, "976052857.337284 0 0 -0.002458");
}

TEST(Trajectory, StampsAreWrittenWithoutAnExponent) {
    // A whole second is the stamp as printed by a logger (1700000000), not 1.7e+09 among the
    // 1700000000.25 of the next line; positions keep the shortest form, exponent and all.
    toposlam::test::TempDir dir;
    Trajectory2D t = {{1700000000.0, {1e-20, 0, 0}}, {1700000000.25, {2, 0, 0}}, {1e40, {}}};
    saveTrajectory(t, dir.file("t.txt"));
    std::ifstream in(dir.file("t.txt"));
    std::string header, first, second;
    std::getline(in, header);
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_EQ(first, "1700000000 1e-20 0 0");
    EXPECT_EQ(second, "1700000000.25 2 0 0");
    const Trajectory2D back = loadTrajectory(dir.file("t.txt"));
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[2].stamp, 1e40);  // too long without an exponent: written with one
}

TEST(Trajectory, CommentsBlankLinesAndTabsAreAccepted) {
    toposlam::test::TempDir dir;
    writeText(dir.file("t.txt"), "# header\n\n1 2 3 0.5\n  # indented comment\n2\t3\t4\t-0.5\r\n");
    const Trajectory2D t = loadTrajectory(dir.file("t.txt"));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[1].stamp, 2.0);
    EXPECT_EQ(t[1].pose.phi, -0.5);
}

TEST(Trajectory, BadInputNamesFileAndLine) {
    toposlam::test::TempDir dir;
    EXPECT_NE(trajectoryLoadError(dir.file("missing.txt")).find("missing.txt: cannot open"),
              std::string::npos);

    writeText(dir.file("fields.txt"), "1 2 3 4\n1 2 3\n");
    EXPECT_NE(trajectoryLoadError(dir.file("fields.txt")).find("line 2: 3 fields, expected 4"),
              std::string::npos);

    writeText(dir.file("extra.txt"), "1 2 3 4 5\n");
    EXPECT_NE(trajectoryLoadError(dir.file("extra.txt")).find("line 1: 5 fields"),
              std::string::npos);

    writeText(dir.file("nan.txt"), "# c\n1 2 nan 4\n");
    EXPECT_NE(trajectoryLoadError(dir.file("nan.txt")).find("line 2: non-finite"),
              std::string::npos);

    writeText(dir.file("word.txt"), "1 2 x 4\n");
    EXPECT_NE(trajectoryLoadError(dir.file("word.txt")).find("line 1: not a number: 'x 4'"),
              std::string::npos);
}

TEST(Trajectory, EmptyTrajectoryRoundTrips) {
    toposlam::test::TempDir dir;
    saveTrajectory({}, dir.file("e.txt"));
    EXPECT_TRUE(loadTrajectory(dir.file("e.txt")).empty());
}
