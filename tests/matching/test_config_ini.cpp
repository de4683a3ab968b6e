// The matcher's options and config_ini/bench-matching-icp.ini.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/slam/CICP.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/mrptslam/CGraphMatcherAlignment.h>

#include <TestSupport.h>

using toposlam::matching::GraphMatcherOptions;

namespace {
std::string configFile(const std::string& name) {
    return toposlam::test::configIni(name);
}
}  // namespace

// graph-matcher.ini holding the defaults and knowing every key is checked for every options
// struct by tests/config/test_all_options.cpp; here what only the matcher has.
TEST(ConfigIni, EveryStepOptionIsReadIncludingBothIcpStages) {
    // The hand-written loader once skipped scanIcp's tolerances (its test listed fields by
    // hand and could not notice); the declaration now serves both ICP stages alike.
    mrpt::config::CConfigFileMemory ini;
    ini.write("GraphScanMatcher", "scan_icp_translation_tolerance", "0.002");
    ini.write("GraphScanMatcher", "scan_icp_rotation_tolerance_deg", "0.5");
    ini.write("GraphScanMatcher", "icp_rotation_tolerance_deg", "1");
    ini.write("GraphScanMatcher", "hough_rotation_bin_deg", "4");
    GraphMatcherOptions o;
    o.loadFromConfigFile(ini, "GraphScanMatcher");
    EXPECT_EQ(o.scanIcp.translationTolerance, 0.002);
    EXPECT_DOUBLE_EQ(o.scanIcp.rotationTolerance, 0.5 * M_PI / 180);
    EXPECT_DOUBLE_EQ(o.icp.rotationTolerance, M_PI / 180);
    EXPECT_DOUBLE_EQ(o.hough.rotationBin, 4 * M_PI / 180);
    EXPECT_EQ(o.icp.translationTolerance, GraphMatcherOptions().icp.translationTolerance);
    // The MRPT interface's section is the matcher's plus two keys of its own.
    ini.write("GraphScanMatcher", "use_guess", "false");
    toposlam::mrptslam::CGraphMatcherAlignment::Options alignment;
    alignment.loadFromConfigFile(ini, "GraphScanMatcher");
    EXPECT_FALSE(alignment.useGuess);
    EXPECT_EQ(alignment.matcher.scanIcp.translationTolerance, 0.002);
    EXPECT_THROW(o.loadFromConfigFile(ini, "GraphScanMatcher"), toposlam::config::ConfigError);
}

TEST(ConfigIni, BenchIcpIniLoads) {
    mrpt::config::CConfigFile ini(configFile("bench-matching-icp.ini"));
    mrpt::slam::CICP::TConfigParams p;
    p.onlyUniqueRobust = false;
    p.loadFromConfigFile(ini, "ICP");
    EXPECT_EQ(p.maxIterations, 80u);
    EXPECT_FLOAT_EQ(p.thresholdDist, 0.5f);
    EXPECT_FLOAT_EQ(p.ALFA, 0.8f);
    EXPECT_TRUE(p.onlyUniqueRobust);
}
