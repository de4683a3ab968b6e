#include <toposlam/io/InputError.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>

#include "GridRay.h"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace toposlam::rooms {

using mrpt::maps::COccupancyGridMap2D;

void FreeSpaceBinarizer::removeSpecksAndLabelObstacles(cv::Mat& all, const cv::Rect& freeBox,
                                                       FreeSpace& out) const {
    // Only the free cells' bounding box plus one ring around it is labelled: everything outside
    // the box is non-free and reaches the map's edge by a straight line, so it is one obstacle
    // per side, joined to the ring on that side, and on the border (the labels are the same
    // partition as labelling the whole map, numbered differently).
    const cv::Rect image(0, 0, all.cols, all.rows);
    const cv::Rect box =
        freeBox.empty() ? image : (freeBox + cv::Size(2, 2) - cv::Point(1, 1)) & image;
    cv::Mat inBox = all(box);
    out.obstacles.create(all.size(), CV_32S);
    cv::Mat labels = out.obstacles(box);
    const int n = runs_.find(inBox, 8, ConnectedRuns::Cells::Zero);
    runs_.paint(labels);
    CV_Assert(labels.data == out.obstacles.ptr(box.y) + box.x * sizeof(int));
    // Outside the box: the label of the ring on that side (rows above and below take the top and
    // bottom ring rows, which also hold the corners).
    if (box.y > 0)
        out.obstacles.rowRange(0, box.y).setTo(labels.at<int>(0, 0));
    if (box.br().y < all.rows)
        out.obstacles.rowRange(box.br().y, all.rows).setTo(labels.at<int>(box.height - 1, 0));
    if (box.x > 0)
        out.obstacles(cv::Rect(0, box.y, box.x, box.height)).setTo(labels.at<int>(0, 0));
    if (box.br().x < all.cols) {
        out.obstacles(cv::Rect(box.br().x, box.y, all.cols - box.br().x, box.height))
            .setTo(labels.at<int>(0, box.width - 1));
    }
    const std::vector<int>& area = runs_.areas();
    // On the border: touching the box's edge (the ring is outside the free box, so joined to
    // the map's edge; where there is no ring the box edge is the map's edge).
    out.obstacleOnBorder.assign(static_cast<std::size_t>(n), 0);
    const int rows = labels.rows, cols = labels.cols;
    for (int r = 0; r < rows; ++r) {
        const int* row = labels.ptr<int>(r);
        out.obstacleOnBorder[static_cast<std::size_t>(row[0])] = 1;
        out.obstacleOnBorder[static_cast<std::size_t>(row[cols - 1])] = 1;
    }
    for (int c = 0; c < cols; ++c) {
        out.obstacleOnBorder[static_cast<std::size_t>(labels.at<int>(0, c))] = 1;
        out.obstacleOnBorder[static_cast<std::size_t>(labels.at<int>(rows - 1, c))] = 1;
    }
    out.obstacleOnBorder[0] = 0;
    const int maxSpeck = static_cast<int>(std::floor(
        detail::toCells(options_.maxSpeckArea, out.frame.resolution * out.frame.resolution)));
    std::vector<std::uint8_t> speck(static_cast<std::size_t>(n), 0);
    out.specksRemoved = 0;
    for (int i = 1; i < n; ++i) {
        if (area[static_cast<std::size_t>(i)] <= maxSpeck &&
            !out.obstacleOnBorder[static_cast<std::size_t>(i)]) {
            speck[static_cast<std::size_t>(i)] = 1;
            ++out.specksRemoved;
        }
    }
    out.unseenHolesFreed = out.unseenHoleCells = 0;
    if (options_.freeUnseenHoles && !out.unknown.empty()) {
        // An island is an unseen hole when every cell of it is unknown.
        std::vector<std::uint8_t> allUnknown(static_cast<std::size_t>(n), 1);
        for (const ConnectedRuns::Run& run : runs_.runs()) {
            const auto label = static_cast<std::size_t>(run.label);
            if (out.obstacleOnBorder[label] || speck[label] || !allUnknown[label])
                continue;
            const std::uint8_t* cells = out.unknown.ptr<std::uint8_t>(box.y + run.row) + box.x;
            allUnknown[label] = std::all_of(cells + run.begin, cells + run.end,
                                            [](std::uint8_t u) { return u != 0; });
        }
        for (int i = 1; i < n; ++i) {
            const auto label = static_cast<std::size_t>(i);
            if (!out.obstacleOnBorder[label] && !speck[label] && allUnknown[label]) {
                speck[label] = 1;
                ++out.unseenHolesFreed;
                out.unseenHoleCells += static_cast<std::size_t>(area[label]);
            }
        }
    }
    out.islandRuns.clear();
    for (const ConnectedRuns::Run& run : runs_.runs()) {
        const auto label = static_cast<std::size_t>(run.label);
        if (speck[label]) {
            std::fill_n(labels.ptr<int>(run.row) + run.begin, run.end - run.begin, 0);
            std::fill_n(inBox.ptr<std::uint8_t>(run.row) + run.begin, run.end - run.begin, 255);
            if (!out.unknown.empty()) {  // a speck made free is no longer unknown
                std::fill_n(out.unknown.ptr<std::uint8_t>(box.y + run.row) + box.x + run.begin,
                            run.end - run.begin, 0);
            }
        } else if (!out.obstacleOnBorder[label]) {
            out.islandRuns.push_back(
                {run.row + box.y, run.begin + box.x, run.end + box.x, run.label});
        }
    }
}

// Specks, obstacles and the largest free region of `all` (255 = free), all within the free
// cells' bounding box: freeing specks inside it does not move it.
void FreeSpaceBinarizer::labelFreeSpace(cv::Mat& all, const std::string& sourceName,
                                        FreeSpace& out) const {
    const cv::Rect freeBox = cv::boundingRect(all);
    removeSpecksAndLabelObstacles(all, freeBox, out);
    keepLargestComponent(all, freeBox, sourceName, out);
}

// Keeps the largest 4-connected component of `all` (255 = free) in out.free and the rest in
// out.otherFree.
void FreeSpaceBinarizer::keepLargestComponent(const cv::Mat& all, const cv::Rect& box,
                                              const std::string& sourceName, FreeSpace& out) const {
    // Only the bounding box of the free cells holds components; 4-connected components are
    // numbered in raster order, which the box keeps (so ties in area go the same way).
    const int n = box.empty() ? 1 : runs_.find(all(box), 4);
    const std::vector<int>& area = runs_.areas();
    int best = 0;
    for (int i = 1; i < n; ++i) {
        if (area[static_cast<std::size_t>(i)] >
            (best == 0 ? 0 : area[static_cast<std::size_t>(best)]))
            best = i;
    }
    if (best == 0) {
        throw io::InputError(sourceName,
                             "the map has no free cell (empty, unknown-only or fully occupied): "
                             "there are no rooms to segment");
    }
    out.free.create(all.size(), CV_8U);
    out.free.setTo(0);
    out.otherFree.create(all.size(), CV_8U);
    out.otherFree.setTo(0);
    out.otherFreeRuns.clear();
    cv::Point first(box.width, box.height), last(-1, -1);  // of the largest region, in the box
    for (const ConnectedRuns::Run& run : runs_.runs()) {
        const bool largest = run.label == best;
        cv::Mat& image = largest ? out.free : out.otherFree;
        std::fill_n(image.ptr<std::uint8_t>(box.y + run.row) + box.x + run.begin,
                    run.end - run.begin, 255);
        if (largest) {
            first = {std::min(first.x, run.begin), std::min(first.y, run.row)};
            last = {std::max(last.x, run.end), std::max(last.y, run.row + 1)};
        } else {
            out.otherFreeRuns.push_back(
                {box.y + run.row, box.x + run.begin, box.x + run.end, run.label});
        }
    }
    out.bounds = cv::Rect(first + box.tl(), last + box.tl());
    out.freeCells = static_cast<std::size_t>(area[static_cast<std::size_t>(best)]);
}

// out.noWall from `all` (255 = free, specks included) and out.unknown (255 = unknown cell; the
// specks made free were cleared from it as they were freed).
void FreeSpaceBinarizer::markNoWall(const cv::Mat& all, FreeSpace& out) const {
    cv::Mat& unknown = out.unknown;
    if (cv::countNonZero(unknown) == 0) {
        out.noWall.release();
        out.unknown.release();
        out.wallHoleReach = 0;
        return;
    }
    out.wallHoleReach = options_.wallHoleReach;
    cv::bitwise_or(all, unknown, nearOccupied_);
    cv::bitwise_not(nearOccupied_, nearOccupied_);  // occupied cells
    const int reach =
        static_cast<int>(std::round(detail::toCells(options_.wallHoleReach, out.frame.resolution)));
    if (reach > 0) {
        cv::dilate(
            nearOccupied_, nearOccupied_,
            cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * reach + 1, 2 * reach + 1)));
    }
    cv::bitwise_and(unknown, ~nearOccupied_, out.noWall);
    cv::bitwise_or(out.noWall, out.free, out.noWall);
}

FreeSpace FreeSpaceBinarizer::binarize(const COccupancyGridMap2D& grid,
                                       const std::string& sourceName) const {
    FreeSpace out;
    binarize(grid, out, sourceName);
    return out;
}

namespace {

// The log-odds values of an occupancy grid's cells whose p(free) passes a test: a range, as
// p(free) grows with the log-odds (empty, lowest > highest, when none passes).
struct LogOddsRange {
    int lowest, highest;

    // out[c] = 255 where cells[c] is in the range, 0 elsewhere; sixteen cells at a time
    // (cv::inRange has no vectorised path for signed bytes).
    void test(const std::int8_t* cells, std::uint8_t* out, int n) const {
        if (lowest > highest) {
            std::fill_n(out, n, 0);
            return;
        }
        const auto low = static_cast<std::int8_t>(lowest), high = static_cast<std::int8_t>(highest);
        int c = 0;
        const cv::v_int8x16 low16 = cv::v_setall_s8(low), high16 = cv::v_setall_s8(high);
        for (; c + 16 <= n; c += 16) {
            const cv::v_int8x16 v = cv::v_load(cells + c);  // unaligned load
            cv::v_store(out + c, cv::v_reinterpret_as_u8((v >= low16) & (v <= high16)));
        }
        for (; c < n; ++c)
            out[c] = cells[c] >= low && cells[c] <= high ? 255 : 0;
    }
};

template <typename Test>
LogOddsRange logOddsWhere(const Test& passes) {
    using Cell = COccupancyGridMap2D::cellType;
    LogOddsRange range{std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
    for (int v = std::numeric_limits<Cell>::min(); v <= std::numeric_limits<Cell>::max(); ++v) {
        if (passes(COccupancyGridMap2D::l2p(static_cast<Cell>(v)))) {
            range.lowest = std::min(range.lowest, v);
            range.highest = std::max(range.highest, v);
        }
    }
    // One range: every value between its ends passes.
    for (int v = range.lowest; v <= range.highest; ++v)
        CV_Assert(passes(COccupancyGridMap2D::l2p(static_cast<Cell>(v))));
    return range;
}

}  // namespace

void FreeSpaceBinarizer::binarize(const COccupancyGridMap2D& grid, FreeSpace& out,
                                  const std::string& sourceName) const {
    out.frame = GridImageFrame{};
    out.frame.resolution = grid.getResolution();
    out.frame.xMin = grid.getXMin();
    out.frame.yMin = grid.getYMin();
    out.frame.cols = static_cast<int>(grid.getSizeX());
    out.frame.rows = static_cast<int>(grid.getSizeY());
    if (out.frame.cols <= 0 || out.frame.rows <= 0) {
        throw io::InputError(sourceName, "the map has no cells: there are no rooms to segment");
    }
    // Cells hold log-odds (int8), and p(free) grows with them: the free cells and the unknown
    // ones are each a range of values, found once, then tested sixteen cells at a time instead
    // of one l2p() per cell.
    using Cell = COccupancyGridMap2D::cellType;
    const LogOddsRange free = logOddsWhere([&](double p) { return p > options_.freeThreshold; });
    const LogOddsRange unknown = logOddsWhere(
        [&](double p) { return p >= options_.occupiedThreshold && p <= options_.freeThreshold; });
    const auto& raw = grid.getRawMap();
    cv::Mat& all = all_;
    all.create(out.frame.rows, out.frame.cols, CV_8U);
    out.unknown.create(out.frame.rows, out.frame.cols, CV_8U);
    static_assert(sizeof(Cell) == 1 && std::is_signed_v<Cell>);
    for (int r = 0; r < out.frame.rows; ++r) {
        // Image row r is the grid's row rows-1-r: the image's y axis points down.
        const auto* cells = reinterpret_cast<const std::int8_t*>(
            raw.data() + static_cast<std::size_t>(out.frame.rows - 1 - r) *
                             static_cast<std::size_t>(out.frame.cols));
        free.test(cells, all.ptr<std::uint8_t>(r), out.frame.cols);
        unknown.test(cells, out.unknown.ptr<std::uint8_t>(r), out.frame.cols);
    }
    labelFreeSpace(all, sourceName, out);
    markNoWall(all, out);
}

FreeSpace FreeSpaceBinarizer::binarize(const cv::Mat& freeImage, GridImageFrame frame,
                                       const std::string& sourceName) const {
    if (freeImage.empty()) {
        throw io::InputError(sourceName, "the map has no cells: there are no rooms to segment");
    }
    CV_Assert(freeImage.type() == CV_8U);
    FreeSpace out;
    frame.cols = freeImage.cols;
    frame.rows = freeImage.rows;
    out.frame = frame;
    cv::compare(freeImage, 0, all_, cv::CMP_NE);
    labelFreeSpace(all_, sourceName, out);
    out.noWall.release();  // free or not: every non-free cell is a wall
    out.unknown.release();
    return out;
}

}  // namespace toposlam::rooms
