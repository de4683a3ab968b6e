// The segmentation does not depend on how the building lies on the grid: a drawn plan turned
// in 5 degree steps from 0 to 90 (nearest neighbour, as a scanned plan or a SLAM grid draws
// it) gives the same rooms (IoU >= 0.9 with the upright result turned the same way) and finds
// every drawn door.
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include "DrawnMaps.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>
#include <set>

using namespace toposlam::rooms;
using toposlam::rooms::test::DrawnMap;
using toposlam::rooms::test::kResolution;

namespace {

// `map` turned by rotateNearest (unknown outside), its points moved along.
DrawnMap turned(const DrawnMap& map, double degrees) {
    cv::Size size;
    const cv::Mat m = rotationOfImage(map.image.size(), degrees, size);
    DrawnMap out = map;
    out.image = rotateNearest(map.image, degrees, 128);
    auto move = [&](const mrpt::math::TPoint2D& p) {
        // World (origin lower-left) -> pixel centre coordinates -> turned -> world.
        const double c = p.x / kResolution - 0.5, r = map.image.rows - p.y / kResolution - 0.5;
        const double c2 = m.at<double>(0, 0) * c + m.at<double>(0, 1) * r + m.at<double>(0, 2);
        const double r2 = m.at<double>(1, 0) * c + m.at<double>(1, 1) * r + m.at<double>(1, 2);
        return mrpt::math::TPoint2D((c2 + 0.5) * kResolution,
                                    (size.height - r2 - 0.5) * kResolution);
    };
    for (auto& p : out.rooms)
        p = move(p);
    for (auto& d : out.doors)
        d.middle = move(d.middle);
    return out;
}

void expectSameAsUpright(const DrawnMap& upright, double degrees) {
    SCOPED_TRACE("turned by " + std::to_string(degrees) + " deg");
    const RoomSegmenter segmenter;
    const auto reference = segmenter.segment(toposlam::rooms::test::gridOf(upright.image));
    const cv::Mat expected = rotateNearest(reference.map.labels, degrees, 0);
    const DrawnMap drawn = turned(upright, degrees);
    const auto result = segmenter.segment(toposlam::rooms::test::gridOf(drawn.image));
    EXPECT_EQ(result.map.rooms.size(), drawn.rooms.size());
    std::set<int> seen;
    for (const auto& p : drawn.rooms) {
        const int id = result.map.roomAt(p.x, p.y);
        ASSERT_GT(id, 0) << "room point (" << p.x << ", " << p.y << ") is in no room";
        EXPECT_TRUE(seen.insert(id).second) << "two drawn rooms share segment " << id;
        const cv::Point cell = result.map.frame.toCell(p.x, p.y);
        const int expectedId = expected.at<int>(cell);
        EXPECT_GE(toposlam::rooms::test::labelIoU(result.map.labels, id, expected, expectedId), 0.9)
            << "room at (" << p.x << ", " << p.y << ")";
    }
    // Every drawn door is found: a door whose middle is within the wall opening (half the wall,
    // a cell, and a cell of turning) of the drawn middle.
    EXPECT_EQ(result.map.doors.size(), drawn.doors.size());
    for (const auto& truth : drawn.doors) {
        EXPECT_LT(toposlam::rooms::test::distanceToNearestDoor(result.map, truth.middle),
                  0.1 + 2 * kResolution + kResolution)
            << "drawn door at (" << truth.middle.x << ", " << truth.middle.y << ")";
    }
}

}  // namespace

TEST(RotationInvariance, OfficeIsTheSameAtEveryAngle) {
    const DrawnMap office = toposlam::rooms::test::office();
    for (int degrees = 0; degrees <= 90; degrees += 5)
        expectSameAsUpright(office, degrees);
}

TEST(RotationInvariance, RotateNearestKeepsLabelsAndTurnsBack) {
    cv::Mat labels(30, 50, CV_32S, cv::Scalar(0));
    labels(cv::Rect(5, 5, 20, 10)).setTo(7);
    labels(cv::Rect(30, 10, 15, 15)).setTo(70000);  // beyond 16 bits
    const cv::Mat turned = rotateNearest(labels, 90, 0);
    EXPECT_EQ(turned.size(), cv::Size(30, 50));
    EXPECT_EQ(cv::countNonZero(turned == 7), 200);
    EXPECT_EQ(cv::countNonZero(turned == 70000), 225);
    EXPECT_EQ(cv::countNonZero(rotateNearest(turned, -90, 0) != labels), 0);
    // Any angle: areas are kept within the boundary's worth of pixels.
    const cv::Mat at17 = rotateNearest(labels, 17, 0);
    EXPECT_NEAR(cv::countNonZero(at17 == 7), 200, 30);
    EXPECT_TRUE(cv::countNonZero(rotateNearest(labels, 0, 0) != labels) == 0);
}
