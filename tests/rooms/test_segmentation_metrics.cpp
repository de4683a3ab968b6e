// The B4 metric (shared/BENCHMARKS.md) on tiny hand-made label images, where every number can
// be counted by hand.
#include <toposlam/rooms/SegmentationMetrics.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace toposlam::rooms;

namespace {

cv::Mat labels(int rows, int cols, int value = 0) {
    return cv::Mat(rows, cols, CV_32S, cv::Scalar(value));
}

}  // namespace

TEST(GroundTruthRooms, WhiteAbove250EightConnectedBiggerThan100) {
    cv::Mat gt(30, 40, CV_8U, cv::Scalar(0));
    gt(cv::Rect(0, 0, 15, 15)) = 255;    // 225 px
    gt(cv::Rect(15, 15, 12, 12)) = 251;  // 144 px, touches the first only diagonally: same room
    gt(cv::Rect(30, 0, 10, 10)) = 255;   // 100 px: dropped (not > 100)
    gt(cv::Rect(30, 20, 10, 10)) = 250;  // not > 250: not a room
    const GroundTruthRooms rooms = groundTruthRooms(gt);
    EXPECT_EQ(rooms.count, 1);
    EXPECT_EQ(cv::countNonZero(rooms.labels), 225 + 144);
}

TEST(BormannPrecisionRecall, CountsOverlapsPerRoomAndPerSegment) {
    // GT: two rooms side by side, 20 x 12 px each (segments must exceed 100 px to count).
    GroundTruthRooms truth;
    truth.labels = labels(12, 40);
    truth.labels(cv::Rect(0, 0, 20, 12)) = 1;
    truth.labels(cv::Rect(20, 0, 20, 12)) = 2;
    truth.count = 2;
    // Segmentation: segment 7 covers room 1 and half of room 2; segment 9 the other half.
    cv::Mat seg = labels(12, 40);
    seg(cv::Rect(0, 0, 30, 12)) = 7;
    seg(cv::Rect(30, 0, 10, 12)) = 9;
    PrecisionRecall pr = bormannPrecisionRecall(truth, seg);
    // Recall: room 1 fully in 7 (1.0), room 2 best half (0.5) -> 0.75.
    EXPECT_DOUBLE_EQ(pr.recall, 0.75);
    EXPECT_EQ(pr.roomRecall, (std::vector<double>{1.0, 0.5}));
    EXPECT_EQ(pr.roomPixels, (std::vector<std::size_t>{240, 240}));
    // Precision: segment 7 best 240/360, segment 9 120/120 -> (2/3 + 1) / 2.
    EXPECT_DOUBLE_EQ(pr.precision, (240.0 / 360 + 1.0) / 2);
    EXPECT_DOUBLE_EQ(pr.recallPixels, 360.0 / 480);
    EXPECT_DOUBLE_EQ(pr.precisionPixels, 360.0 / 480);
    EXPECT_EQ(pr.segments, 2);
}

TEST(BormannPrecisionRecall, UnassignedLabelIsASegmentAndTinySegmentsAreIgnored) {
    GroundTruthRooms truth;
    truth.labels = labels(20, 20, 1);
    truth.count = 1;
    cv::Mat seg = labels(20, 20, 3);
    seg(cv::Rect(0, 0, 20, 10)) = kUnassignedLabel;  // 200 px of "unassigned free space"
    seg(cv::Rect(0, 10, 10, 10)) = 5;                // 100 px, and 3 keeps 100: both ignored
    const PrecisionRecall pr = bormannPrecisionRecall(truth, seg);
    EXPECT_EQ(pr.segments, 1);  // only 65280 has more than 100 px
    EXPECT_DOUBLE_EQ(pr.precision, 1.0);
    EXPECT_DOUBLE_EQ(pr.recall, 200.0 / 400);  // the best scored segment covers half of the room
    EXPECT_EQ(countSegments(seg), 2);          // 3 and 5; 65280 is not counted, tiny ones are
    EXPECT_EQ(pr.unassignedPixels, 200u);
    EXPECT_DOUBLE_EQ(pr.precisionOfRooms, 0.0);  // no segment but 65280
}

TEST(BormannPrecisionRecall, PrecisionOfRoomsLeavesTheUnassignedSegmentOut) {
    // One room of 20 x 20 px; segment 4 covers it; 65280 holds 150 px outside it.
    GroundTruthRooms truth;
    truth.labels = labels(20, 30);
    truth.labels(cv::Rect(0, 0, 20, 20)) = 1;
    truth.count = 1;
    cv::Mat seg = labels(20, 30);
    seg(cv::Rect(0, 0, 20, 20)) = 4;
    seg(cv::Rect(20, 0, 10, 15)) = kUnassignedLabel;
    const PrecisionRecall pr = bormannPrecisionRecall(truth, seg);
    EXPECT_EQ(pr.segments, 2);
    EXPECT_DOUBLE_EQ(pr.precision, (1.0 + 0.0) / 2);
    EXPECT_DOUBLE_EQ(pr.precisionOfRooms, 1.0);
    EXPECT_EQ(pr.unassignedPixels, 150u);
}

TEST(OpenFloorOfRooms, DropsTheRoomPixelsNextToWallsAndFurnitureAndKeepsLabels) {
    // Free 30 x 20 px with a 2 px wall at column 15 (two rooms) and a 2 x 2 px table in room 1.
    cv::Mat free(20, 30, CV_8U, cv::Scalar(255));
    free(cv::Rect(15, 0, 2, 20)) = 0;
    free(cv::Rect(5, 8, 2, 2)) = 0;
    GroundTruthRooms truth;
    truth.labels = labels(20, 30);
    truth.labels(cv::Rect(0, 0, 15, 20)) = 1;  // the table's pixels belong to the room
    truth.labels(cv::Rect(17, 0, 13, 20)) = 2;
    truth.count = 2;
    const GroundTruthRooms open = openFloorOfRooms(truth, free);
    EXPECT_EQ(open.count, 2);
    // Room 1 loses its column next to the wall (20 px) and the table with its ring (4 x 4 px);
    // the image border is no wall.
    EXPECT_EQ(cv::countNonZero(open.labels == 1), 15 * 20 - 20 - 16);
    EXPECT_EQ(open.labels.at<int>(0, 13), 1);
    EXPECT_EQ(open.labels.at<int>(0, 14), 0);
    EXPECT_EQ(open.labels.at<int>(9, 7), 0);
    EXPECT_EQ(open.labels.at<int>(9, 8), 1);
    EXPECT_EQ(cv::countNonZero(open.labels == 2), 13 * 20 - 20);
    EXPECT_EQ(open.labels.at<int>(0, 17), 0);
}

TEST(OpenFloorOfRooms, ARoomWithTooLittleOpenFloorStaysWhole) {
    // A corridor 3 px wide between walls: 1 px of open floor per row, 40 px in all (<= 100).
    cv::Mat free(5, 40, CV_8U, cv::Scalar(0));
    free(cv::Rect(0, 1, 40, 3)) = 255;
    GroundTruthRooms truth;
    truth.labels = labels(5, 40);
    truth.labels(cv::Rect(0, 1, 40, 3)) = 1;
    truth.count = 1;
    const GroundTruthRooms open = openFloorOfRooms(truth, free);
    EXPECT_EQ(cv::countNonZero(open.labels == 1), 120);
}

TEST(DoorMetric, GapFillingJoinsLabelsAcrossDrawnSeparators) {
    // Two rooms separated by a 3 px free separator (drawn GT line) and a wall with an opening.
    cv::Mat free(10, 23, CV_8U, cv::Scalar(255));
    cv::Mat l = labels(10, 23);
    l(cv::Rect(0, 0, 10, 10)) = 1;
    l(cv::Rect(13, 0, 10, 10)) = 2;
    free(cv::Rect(10, 0, 3, 4)) = 0;  // wall from the top, opening rows 4..9
    const auto doors = labelBoundaryDoors(l, free);
    ASSERT_EQ(doors.size(), 1u);
    EXPECT_EQ(doors[0].labelA, 1);
    EXPECT_EQ(doors[0].labelB, 2);
    // The FIFO search fills the separator from both sides; label 1's seeds come first in raster
    // order, so it takes columns 10 and 11, label 2 column 12. The boundary is between columns
    // 11 and 12 in the 6 open rows: 2 pixels per row.
    EXPECT_EQ(doors[0].pixels.size(), 12u);
    for (const auto& p : doors[0].pixels)
        EXPECT_GE(p.y, 4);
}

TEST(DoorMetric, GapFillingStopsAfterFiveStepsAndAtWalls) {
    cv::Mat free(5, 30, CV_8U, cv::Scalar(255));
    cv::Mat l = labels(5, 30);
    l(cv::Rect(0, 0, 5, 5)) = 1;
    l(cv::Rect(17, 0, 13, 5)) = 2;  // 12 free px between: 5 + 5 steps leave 2 px unlabelled
    EXPECT_TRUE(labelBoundaryDoors(l, free).empty());
    l(cv::Rect(15, 0, 2, 5)) = 2;  // now 10 px between: the fronts meet
    EXPECT_EQ(labelBoundaryDoors(l, free).size(), 1u);
    free(cv::Rect(9, 0, 1, 5)) = 0;  // a wall in between: no door
    EXPECT_TRUE(labelBoundaryDoors(l, free).empty());
}

TEST(DoorMetric, OneDoorPerLabelPairEvenInPieces) {
    // Labels 1 and 2 touch in two separate places (an opening between pillars): one door.
    cv::Mat free(12, 10, CV_8U, cv::Scalar(255));
    cv::Mat l = labels(12, 10);
    l(cv::Rect(0, 0, 5, 12)) = 1;
    l(cv::Rect(5, 0, 5, 12)) = 2;
    free(cv::Rect(4, 4, 2, 4)) = 0;
    l.setTo(0, free == 0);
    const auto doors = labelBoundaryDoors(l, free);
    ASSERT_EQ(doors.size(), 1u);
    EXPECT_EQ(doors[0].pixels.size(), 16u);  // rows 0-3 and 8-11, columns 4 and 5
    // Representative: the pixel nearest the mean (4.5, 5.5); ties -> first in raster order.
    EXPECT_EQ(doors[0].representative, cv::Point(4, 3));
}

TEST(DoorMetric, MatchingWithinTolerance) {
    LabelBoundaryDoor t1{1, 2, {{10, 10}, {10, 11}}, {10, 10}};
    LabelBoundaryDoor t2{2, 3, {{50, 50}}, {50, 50}};
    LabelBoundaryDoor v1{4, 5, {{18, 16}}, {18, 16}};  // 10 px from (10, 10): matches
    LabelBoundaryDoor v2{5, 6, {{30, 30}}, {30, 30}};  // matches nothing
    LabelBoundaryDoor v3{6, 7, {{19, 17}}, {19, 17}};  // sqrt(81 + 36) > 10 from (10, 11)
    const DoorMatchCounts c = matchDoors({v1, v2, v3}, {t1, t2}, 10.0);
    EXPECT_EQ(c.virtualDoors, 3u);
    EXPECT_EQ(c.matchedVirtual, 1u);
    EXPECT_EQ(c.trueDoors, 2u);
    EXPECT_EQ(c.matchedTrue, 1u);
    EXPECT_EQ(matchDoors({v1, v3}, {t1}, 20.0).matchedVirtual, 2u);
}

TEST(DoorMetric, SegmentSideDropsUnassignedAndTinySegments) {
    cv::Mat seg = labels(20, 20, 4);
    seg(cv::Rect(0, 0, 20, 10)) = kUnassignedLabel;
    seg(cv::Rect(0, 0, 5, 5)) = 8;  // 25 px
    const cv::Mat l = doorMetricSegmentLabels(seg);
    EXPECT_EQ(cv::countNonZero(l), 200);
    EXPECT_EQ(l.at<int>(15, 15), 4);
}
