// The front end's settings as its parts get them (GraphSlamOptions::lineMapOptions(),
// icpOptions()), and toposlam-bench-submap, which times those parts with them.
#include <gtest/gtest.h>
#include <toposlam/mapping/GraphSlamOptions.h>

#include "TestSupport.h"

namespace toposlam::mapping {
namespace {

using test::runApp;

TEST(FrontEndSettings, TheSubmapsLineMapAndIcpFollowTheIniKeys) {
    GraphSlamOptions o;
    o.mapResolution = 0.04;
    o.icpMaxDistance = 0.35;
    o.mapFuseDistance = 0.03;
    o.mapConfirmDistance = 0.12;
    o.mapMaxRange = 25;
    o.icpMaxIterations = 9;
    o.icpRobustScale = 0.07;
    o.icpStride = 3;
    o.icpMinViews = 2;
    o.icpMaxIncidence = 1.2;
    const matching::LineMapOptions map = o.lineMapOptions();
    EXPECT_DOUBLE_EQ(map.resolution, 0.04);
    EXPECT_DOUBLE_EQ(map.radius, 0.35);  // the lookup reaches as far as ICP associates
    EXPECT_DOUBLE_EQ(map.fuseDistance, 0.03);
    EXPECT_DOUBLE_EQ(map.confirmDistance, 0.12);
    EXPECT_DOUBLE_EQ(map.maxRange, 25);
    EXPECT_DOUBLE_EQ(map.carveMargin, 0);
    const matching::IcpOptions icp = o.icpOptions();
    EXPECT_EQ(icp.maxIterations, 9);
    EXPECT_DOUBLE_EQ(icp.maxDistance, 0.35);
    EXPECT_DOUBLE_EQ(icp.robustScale, 0.07);
    EXPECT_EQ(icp.stride, 3u);
    EXPECT_EQ(icp.minMapViews, 2u);
    EXPECT_DOUBLE_EQ(icp.maxIncidence, 1.2);
    EXPECT_FALSE(icp.skipMovedMapPoints);

    // Free-space carving: the maps count views through their points, ICP skips moved ones.
    o.freeSpaceCarving = true;
    EXPECT_DOUBLE_EQ(o.lineMapOptions().carveMargin, kSeenThroughMargin);
    EXPECT_TRUE(o.icpOptions().skipMovedMapPoints);
}

TEST(FrontEndSettings, TheHotLoopsBenchmarkTimesTheDemoLog) {
    // No data folder: the office alone, the others skipped with a note.
    const auto run = runApp("toposlam-bench-submap",
                            "--data /nonexistent-toposlam-data --benchmark_min_time=0.01");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("insert/office"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("icp/office"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("not found; intel skipped"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("keyframes/s"), std::string::npos) << run.output;

    const auto missing = runApp("toposlam-bench-submap", "-c /nonexistent-toposlam.ini");
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("error: /nonexistent-toposlam.ini: no such file"),
              std::string::npos)
        << missing.output;
    EXPECT_EQ(runApp("toposlam-bench-submap", "--no-such-flag").exitCode, 2);
}

}  // namespace
}  // namespace toposlam::mapping
