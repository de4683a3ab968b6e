// The two ipa_room_segmentation baselines of B4 on drawn maps.
#include <toposlam/rooms/BormannBaselines.h>
#include <toposlam/rooms/DistanceSegmentation.h>
#include <toposlam/rooms/MorphologicalSegmentation.h>
#include <toposlam/rooms/SegmentationMetrics.h>

#include "DrawnMaps.h"

#include <gtest/gtest.h>

using namespace toposlam::rooms;

namespace {

// Two 6 x 6 m rooms joined by a 0.9 m door; 255 free, 0 occupied (the package's input). Big
// enough that both together exceed the morphological upper limit (47 m^2) until the erosion
// has closed the door (9 steps).
cv::Mat twoRooms() {
    cv::Mat img(130, 254, CV_8U, cv::Scalar(0));
    img(cv::Rect(5, 5, 120, 120)) = 255;
    img(cv::Rect(129, 5, 120, 120)) = 255;
    img(cv::Rect(125, 56, 4, 18)) = 255;
    return img;
}

}  // namespace

TEST(WavefrontRegionGrowing, TakesTheFirstLabelledNeighbourOfThePreviousPass) {
    cv::Mat l(5, 7, CV_32S, cv::Scalar(kUnassignedLabel));
    l.row(0).setTo(0);
    l.row(4).setTo(0);
    l.at<int>(2, 1) = 3;
    l.at<int>(2, 5) = 8;
    wavefrontRegionGrowing(l);
    // Column 3 is reached by both in the same pass; scan order (columns -1 first) gives 3.
    EXPECT_EQ(l.at<int>(2, 3), 3);
    EXPECT_EQ(l.at<int>(1, 4), 8);
    EXPECT_EQ(l.at<int>(0, 3), 0);  // obstacles stay
    // The outermost columns are never filled (as in the package).
    EXPECT_EQ(l.at<int>(2, 0), kUnassignedLabel);
}

TEST(MorphologicalSegmentation, SplitsTwoRoomsAtTheirDoor) {
    const cv::Mat map = twoRooms();
    const cv::Mat seg = MorphologicalSegmentation().segment(map, test::kResolution);
    EXPECT_EQ(countSegments(seg), 2);
    EXPECT_NE(seg.at<int>(50, 50), seg.at<int>(50, 160));
    EXPECT_EQ(seg.at<int>(0, 0), 0);
}

TEST(DistanceSegmentation, SplitsTwoRoomsAtTheirDoor) {
    const cv::Mat map = twoRooms();
    const cv::Mat seg = DistanceSegmentation().segment(map, test::kResolution);
    EXPECT_EQ(countSegments(seg), 2);
    EXPECT_NE(seg.at<int>(50, 50), seg.at<int>(50, 160));
}
