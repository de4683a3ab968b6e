// How far a scan's readings go into the submaps (MapRange.h).
#include <gtest/gtest.h>
#include <toposlam/mapping/MapRange.h>

#include <vector>

namespace toposlam::mapping {
namespace {

// 100 valid readings over 180 degrees (80 m laser), `far` of them at 30 m, the rest at 5 m,
// plus 20 invalid ones (no return), which count for nothing.
matching::PolarScan scanWithFarReadings(std::size_t far) {
    std::vector<float> ranges(120, 5.0f);
    std::vector<char> valid(120, 1);
    for (std::size_t i = 0; i < far; ++i)
        ranges[i] = 30.0f;
    for (std::size_t i = 100; i < 120; ++i)
        ranges[i] = 80.0f, valid[i] = 0;
    matching::PolarScan scan;
    scan.assign(-M_PI / 2, M_PI / 119, ranges, valid, 80.0);
    return scan;
}

TEST(MapRange, FarReadingsGoInOnlyWhenTheyAreAFairShareOfTheScan) {
    GraphSlamOptions options;  // map_max_range 20 m, map_far_share 0.1
    EXPECT_DOUBLE_EQ(mapRange(scanWithFarReadings(0), options), 20.0);
    EXPECT_DOUBLE_EQ(mapRange(scanWithFarReadings(10), options), 20.0) << "10 % is not more";
    EXPECT_DOUBLE_EQ(mapRange(scanWithFarReadings(11), options), 80.0) << "the sensor's range";
    options.mapFarShare = 1;  // never
    EXPECT_DOUBLE_EQ(mapRange(scanWithFarReadings(100), options), 20.0);
    options.mapFarShare = 0.1;
    options.mapMaxRange = 100;  // beyond the sensor: stays what was asked
    EXPECT_DOUBLE_EQ(mapRange(scanWithFarReadings(100), options), 100.0);
}

}  // namespace
}  // namespace toposlam::mapping
