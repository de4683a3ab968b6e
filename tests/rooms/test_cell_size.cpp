// The segmentation does not depend on the grid's cell size: a drawn plan mapped in 0.10 m and
// 0.15 m cells (pooled as a laser grid marks them: a cell with any wall in it is not free), or in
// 0.025 m and 0.0125 m cells (each pixel split), gives the same rooms as in its drawn 0.05 m
// pixels (IoU >= 0.9 once each cell's label is carried back to the pixels) and finds every drawn
// door; and B4's pooled and split cases are built and scored in the drawn ground truth's frame.
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/RoomBenchmarkCase.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include "DrawnMaps.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <set>
#include <stdexcept>

using namespace toposlam::rooms;
using toposlam::rooms::test::DrawnMap;
using toposlam::rooms::test::kResolution;

namespace {

// The drawn plan as B4 hands it over (free = 255, everything else a wall), its rooms labelled
// by the segmentation of the drawn pixels.
RoomBenchmarkCase drawnCaseOf(const DrawnMap& map, const cv::Mat& roomLabels) {
    const cv::Mat free = map.image == 255;
    return drawnCase("test", "office", false, 0, free, free, roomLabels, kResolution);
}

void expectSameAsDrawn(const DrawnMap& map, double cellSize) {
    SCOPED_TRACE("cells of " + std::to_string(cellSize) + " m");
    const RoomSegmenter segmenter;
    const cv::Mat free = map.image == 255;
    const auto reference = segmenter.segment(gridOfFreeImage(free, kResolution));
    ASSERT_EQ(reference.map.rooms.size(), map.rooms.size());

    const RoomBenchmarkCase mapped =
        caseAtCellSize(drawnCaseOf(map, reference.map.labels), cellSize);
    EXPECT_NEAR(mapped.grid.getResolution(), cellSize, 1e-6);  // MRPT keeps it as a float
    const auto result = segmenter.segment(mapped.grid);
    EXPECT_EQ(result.map.rooms.size(), map.rooms.size());
    const cv::Mat labels = mapped.toTruthFrame(result.map.labels);
    ASSERT_EQ(labels.size(), free.size());
    std::set<int> seen;
    for (const auto& p : map.rooms) {
        // Same origin: the same world point is in the same room of both grids.
        const int id = result.map.roomAt(p.x, p.y);
        ASSERT_GT(id, 0) << "room point (" << p.x << ", " << p.y << ") is in no room";
        EXPECT_TRUE(seen.insert(id).second) << "two drawn rooms share segment " << id;
        const cv::Point pixel = reference.map.frame.toCell(p.x, p.y);
        EXPECT_EQ(labels.at<int>(pixel), id);
        EXPECT_GE(toposlam::rooms::test::labelIoU(labels, id, reference.map.labels,
                                                  reference.map.labels.at<int>(pixel)),
                  0.9)
            << "room at (" << p.x << ", " << p.y << ")";
    }
    // Every drawn door is found: within half the wall, a cell of pooling and a cell of the
    // door's own quantisation of the drawn middle (finer cells: closer).
    EXPECT_EQ(result.map.doors.size(), map.doors.size());
    for (const auto& truth : map.doors) {
        EXPECT_LT(toposlam::rooms::test::distanceToNearestDoor(result.map, truth.middle),
                  0.1 + 2 * cellSize)
            << "drawn door at (" << truth.middle.x << ", " << truth.middle.y << ")";
    }
}

// The drawn office as B4 hands it over, its ground truth the segmentation of its pixels.
RoomBenchmarkCase officeCase() {
    const DrawnMap office = toposlam::rooms::test::office();
    const auto reference =
        RoomSegmenter().segment(gridOfFreeImage(office.image == 255, kResolution));
    return drawnCaseOf(office, reference.map.labels);
}

// B4 scores the case (the office in other cells) in the drawn ground truth about as the drawn
// plan: rooms within 3 %, and every door matched within 0.5 m of the drawn plan's pixels, not
// of the cells.
void expectScoredAsDrawn(const RoomBenchmarkCase& mapped) {
    RoomBenchmarkOptions options;
    options.methods = {"vdoor"};
    options.repeats = 1;
    const auto scores = RoomBenchmark(options).score(mapped);
    ASSERT_EQ(scores.size(), 1u);
    EXPECT_GE(scores[0].pr.recall, 0.97);
    EXPECT_GE(scores[0].pr.precision, 0.97);
    EXPECT_EQ(scores[0].doors.matchedTrue, scores[0].doors.trueDoors);
    EXPECT_EQ(scores[0].doors.matchedVirtual, scores[0].doors.virtualDoors);
}

}  // namespace

TEST(CellSize, OfficeIsTheSameInCoarserCells) {
    const DrawnMap office = toposlam::rooms::test::office();
    for (const double cellSize : {0.10, 0.15})
        expectSameAsDrawn(office, cellSize);
}

TEST(CellSize, OfficeIsTheSameInFinerCells) {
    // The thresholds in cells (a wall's thickness counted within a cell, WallThickness) must
    // not tighten on a finer grid.
    const DrawnMap office = toposlam::rooms::test::office();
    for (const double cellSize : {0.025, 0.0125})
        expectSameAsDrawn(office, cellSize);
}

TEST(CellSize, ThinWallsHoldInCoarserCells) {
    // 0.1 m (two-pixel) partitions: in 0.1 m cells each is one or two cells thick, depending
    // on where it falls on the cells.
    expectSameAsDrawn(toposlam::rooms::test::thinWalls(), 0.10);
}

TEST(CellSize, PoolingMarksACellWithAnyWallInIt) {
    // 5 x 7 pixels in cells of 2 x 2, aligned to the lower-left corner: the top row of cells
    // and the right column reach past the image and are not free.
    cv::Mat free(5, 7, CV_8U, cv::Scalar(255));
    free.at<std::uint8_t>(3, 2) = 0;  // in the cell of rows 3-4, columns 2-3
    const cv::Mat cells = poolFreeImage(free, 2);
    ASSERT_EQ(cells.size(), cv::Size(4, 3));
    const std::uint8_t expected[3][4] = {{0, 0, 0, 0}, {255, 255, 255, 0}, {255, 0, 255, 0}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_EQ(cells.at<std::uint8_t>(r, c), expected[r][c]) << "cell " << r << ", " << c;
    EXPECT_EQ(cv::countNonZero(poolFreeImage(free, 1) != free), 0);
}

TEST(CellSize, PooledCaseIsScoredInTheDrawnGroundTruth) {
    const RoomBenchmarkCase drawn = officeCase();
    const RoomBenchmarkCase pooled = pooledCase(drawn, 0.1);
    EXPECT_EQ(pooled.inputFree.cols, (drawn.inputFree.cols + 1) / 2);
    EXPECT_EQ(pooled.inputFree.rows, (drawn.inputFree.rows + 1) / 2);
    EXPECT_NEAR(pooled.truthResolution, kResolution, 1e-6);
    EXPECT_EQ(pooled.truth.count, drawn.truth.count);
    // Every free pixel of the drawn plan has a label once the cells' labels are carried back,
    // those along the walls in cells that a wall made not free included (the office's 0.2 m
    // walls lie on 0.1 m cells, not on 0.15 m ones).
    const RoomBenchmarkCase coarser = pooledCase(drawn, 0.15);
    const auto result = RoomSegmenter().segment(coarser.grid);
    const cv::Mat labels =
        coarser.toTruthFrame(RoomBenchmark::scoredLabels(result.map, coarser.inputFree));
    ASSERT_EQ(labels.size(), drawn.inputFree.size());
    cv::Mat cellsFree;
    cv::resize(coarser.inputFree, cellsFree, cv::Size(), 3, 3, cv::INTER_NEAREST);
    EXPECT_GT(cv::countNonZero(drawn.inputFree != 0), cv::countNonZero(cellsFree != 0) + 1000);
    EXPECT_EQ(cv::countNonZero((labels == 0) & (drawn.inputFree != 0)), 0);

    expectScoredAsDrawn(pooled);

    // The drawn resolution itself: the case as it is.
    EXPECT_EQ(pooledCase(drawn, kResolution).inputFree.data, drawn.inputFree.data);
}

TEST(CellSize, SplitCaseIsScoredInTheDrawnGroundTruth) {
    const RoomBenchmarkCase drawn = officeCase();
    const RoomBenchmarkCase split = splitCase(drawn, 0.025);
    EXPECT_EQ(split.inputFree.size(), drawn.inputFree.size() * 2);
    EXPECT_NEAR(split.truthResolution, kResolution, 1e-6);
    // A label image in cells comes back with each pixel's majority: the 2 x 2 cells of pixel
    // (0, 0) hold 7, 7, 7 and 9.
    cv::Mat cells(split.inputFree.size(), CV_32S, cv::Scalar(3));
    cells.at<int>(0, 0) = cells.at<int>(0, 1) = cells.at<int>(1, 0) = 7;
    cells.at<int>(1, 1) = 9;
    const cv::Mat back = split.toTruthFrame(cells);
    ASSERT_EQ(back.size(), drawn.inputFree.size());
    EXPECT_EQ(back.at<int>(0, 0), 7);
    EXPECT_EQ(back.at<int>(1, 1), 3);

    expectScoredAsDrawn(split);
}

TEST(CellSize, RejectsACellSizeThatIsNoWholeMultiple) {
    const DrawnMap office = toposlam::rooms::test::office();
    const RoomBenchmarkCase drawn =
        drawnCaseOf(office, cv::Mat(office.image.size(), CV_32S, cv::Scalar(0)));
    EXPECT_THROW(pooledCase(drawn, 0.07), std::invalid_argument);
    EXPECT_THROW(pooledCase(drawn, 0.025), std::invalid_argument);
    EXPECT_THROW(pooledCase(drawn, 0), std::invalid_argument);
    EXPECT_THROW(splitCase(drawn, 0.03), std::invalid_argument);
    EXPECT_THROW(splitCase(drawn, 0.05 / 9), std::invalid_argument);
    EXPECT_THROW(checkCellSize(0.07, kResolution), std::invalid_argument);
    EXPECT_NO_THROW(checkCellSize(0.025, kResolution));
    EXPECT_NO_THROW(checkCellSize(0.15, kResolution));
    RoomBenchmarkCase mapped = drawn;
    mapped.toTruthFrame = [](const cv::Mat& labels) { return labels; };
    EXPECT_THROW(pooledCase(mapped, 0.1), std::invalid_argument);
    EXPECT_THROW(splitCase(mapped, 0.025), std::invalid_argument);
}
