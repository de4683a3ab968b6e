// A submap's parts (Submap.h): a keyframe placed by odometry alone starts one, and a scan is tied
// to the part most of its readings lie on.
#include <gtest/gtest.h>
#include <toposlam/mapping/Submap.h>
#include <toposlam/matching/PointToLineIcp.h>

#include <cmath>
#include <limits>
#include <vector>

namespace toposlam::mapping {
namespace {

// A scan from the origin over 180 deg (1 deg steps) that sees the wall x = 2 ahead where
// `ahead` and the wall y = 3 on its left where `left`; no return elsewhere.
matching::PolarScan scanOfWalls(bool ahead, bool left) {
    std::vector<float> ranges(181, 0.0f);
    std::vector<char> valid(181, 0);
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        const double bearing = -M_PI / 2 + double(i) * M_PI / 180;
        const double c = std::cos(bearing), s = std::sin(bearing);
        double range = std::numeric_limits<double>::infinity();
        if (ahead && c > 1e-6)
            range = std::min(range, 2.0 / c);
        if (left && s > 1e-6)
            range = std::min(range, 3.0 / s);
        if (range < 10)
            ranges[i] = float(range), valid[i] = 1;
    }
    matching::PolarScan scan;
    scan.assign(-M_PI / 2, M_PI / 180, ranges, valid, 10.0);
    return scan;
}

Keyframe keyframeOf(std::size_t id, const matching::PolarScan& scan, bool placedByOdometry) {
    Keyframe kf;
    kf.id = id;
    if (placedByOdometry)
        kf.placedByOdometry = mrpt::math::CMatrixDouble33::Identity();
    matching::surfacePoints(scan, matching::LineMapOptions(), kf.surface);
    return kf;
}

TEST(Submap, AScanIsTiedToThePartItsReadingsLieOn) {
    // Keyframe 3 (the anchor) saw the wall ahead; keyframe 4, placed by odometry alone, the
    // wall on the left as well, which nothing before it had seen.
    const matching::PolarScan wallAhead = scanOfWalls(true, false);
    const matching::PolarScan wallLeft = scanOfWalls(false, true);
    const matching::PolarScan both = scanOfWalls(true, true);
    Submap submap(3, matching::LineMapOptions());
    submap.insert(keyframeOf(3, wallAhead, false), mrpt::poses::CPose2D());
    submap.insert(keyframeOf(4, both, true), mrpt::poses::CPose2D());
    EXPECT_EQ(submap.partStarts(), (std::vector<std::size_t>{3, 4}));
    EXPECT_EQ(submap.partHolding(wallAhead, mrpt::poses::CPose2D(), 0.05), 3u)
        << "the wall ahead was the anchor's: keyframe 4's readings of it were fused into it";
    EXPECT_EQ(submap.partHolding(wallLeft, mrpt::poses::CPose2D(), 0.05), 4u);
    // Nothing of the scan on the map: the anchor.
    EXPECT_EQ(submap.partHolding(wallLeft, mrpt::poses::CPose2D(0, 20, 0), 0.05), 3u);
    // Rebuilt (after an optimisation), the parts are the same.
    const std::vector<std::size_t> members = submap.keyframes();
    submap.clear();
    EXPECT_EQ(submap.partStarts(), std::vector<std::size_t>{3});
    submap.insert(keyframeOf(3, wallAhead, false), mrpt::poses::CPose2D());
    submap.insert(keyframeOf(4, both, true), mrpt::poses::CPose2D());
    EXPECT_EQ(submap.partHolding(wallLeft, mrpt::poses::CPose2D(), 0.05), 4u);
}

TEST(Submap, CountsReadingsOnTheMapBeforeItsNewestPart) {
    // The anchor saw the wall ahead; keyframe 4, placed by odometry alone, both walls. A scan of
    // both lies on the whole map, but before keyframe 4's part nearly only on the wall ahead (a
    // reading counts for the part of its nearest map point: keyframe 4 added a few points of
    // the wall ahead beside the anchor's).
    const matching::PolarScan wallAhead = scanOfWalls(true, false);
    const matching::PolarScan wallLeft = scanOfWalls(false, true);
    const matching::PolarScan both = scanOfWalls(true, true);
    const mrpt::poses::CPose2D origin;
    const auto onWholeMap = [](const Submap& s, const matching::PolarScan& scan) {
        return matching::PointToLineIcp::countOnMap(s.map(), scan, mrpt::poses::CPose2D(), 0.05);
    };
    Submap submap(3, matching::LineMapOptions());
    submap.insert(keyframeOf(3, wallAhead, false), origin);
    const std::size_t ahead = onWholeMap(submap, wallAhead);
    ASSERT_GT(ahead, 30u);
    EXPECT_EQ(submap.readingsBeforeNewestPart(both, origin, 0.05), onWholeMap(submap, both))
        << "one part: the whole map counts";
    submap.insert(keyframeOf(4, both, true), origin);
    const std::size_t before = submap.readingsBeforeNewestPart(both, origin, 0.05);
    EXPECT_GT(before, ahead / 2);
    EXPECT_LT(before + 30, onWholeMap(submap, both)) << "the left wall is keyframe 4's";
    EXPECT_LT(submap.readingsBeforeNewestPart(wallLeft, origin, 0.05),
              onWholeMap(submap, wallLeft) / 10);
}

TEST(Submap, KeyframesPlacedByRegistrationAndTheAnchorStartNoPart) {
    const matching::PolarScan wallAhead = scanOfWalls(true, false);
    const matching::PolarScan wallLeft = scanOfWalls(false, true);
    Submap byIcp(0, matching::LineMapOptions());
    byIcp.insert(keyframeOf(0, wallAhead, false), mrpt::poses::CPose2D());
    byIcp.insert(keyframeOf(1, wallLeft, false), mrpt::poses::CPose2D());
    EXPECT_EQ(byIcp.partStarts(), std::vector<std::size_t>{0});
    EXPECT_EQ(byIcp.partHolding(wallLeft, mrpt::poses::CPose2D(), 0.05), 0u);
    // An anchor placed by odometry is the submap's frame: everything in it is rigid to it.
    Submap anchoredByOdometry(7, matching::LineMapOptions());
    anchoredByOdometry.insert(keyframeOf(7, wallAhead, true), mrpt::poses::CPose2D());
    anchoredByOdometry.insert(keyframeOf(8, wallLeft, false), mrpt::poses::CPose2D());
    EXPECT_EQ(anchoredByOdometry.partStarts(), std::vector<std::size_t>{7});
}

}  // namespace
}  // namespace toposlam::mapping
