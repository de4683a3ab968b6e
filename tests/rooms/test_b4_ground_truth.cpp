// The ground truth of B4 as BENCHMARKS.md counts it: 557 rooms and 599 true doors over the 20
// benchmark maps. Checks GT-room extraction and the door metric's steps 1-4 on the real data.
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/SegmentationMetrics.h>

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

using namespace toposlam::rooms;

TEST(B4GroundTruth, RoomsAndDoorsOfTheTwentyMapsMatchTheDocumentedCounts) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(first, "rooms/lab_ipa_gt_segmentation.png");
    const std::string dir = toposlam::test::sharedDataDir() + "/rooms/";
    int rooms = 0;
    std::size_t doors = 0;
    for (const std::string& name : RoomBenchmark::benchmarkMaps()) {
        const cv::Mat gt = cv::imread(dir + name + "_gt_segmentation.png", cv::IMREAD_GRAYSCALE);
        const cv::Mat grey = cv::imread(dir + name + ".png", cv::IMREAD_GRAYSCALE);
        ASSERT_FALSE(gt.empty() || grey.empty()) << name;
        cv::Mat free;
        cv::threshold(grey, free, 249, 255, cv::THRESH_BINARY);
        const GroundTruthRooms truth = groundTruthRooms(gt);
        rooms += truth.count;
        doors += labelBoundaryDoors(truth.labels, free).size();
    }
    EXPECT_EQ(rooms, 557);
    EXPECT_EQ(doors, 599u);
}
