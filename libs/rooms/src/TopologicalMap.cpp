#include <toposlam/rooms/TopologicalMap.h>

#include "LabelRuns.h"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

// What one raster pass over a room's cells gives.
struct RoomCells {
    std::size_t cells = 0;
    double sumCol = 0, sumRow = 0;
    int minCol = 1 << 30, minRow = 1 << 30, maxCol = -1, maxRow = -1;
    float deepest = -1;
    cv::Point anchor;  // the first cell (raster order) of the greatest depth
};

// Per room id 1..N (index id - 1): its cells, their sums, bounding box and deepest cell. Each
// row is taken run by run (cells of one room side by side): the sums of whole numbers are exact
// in a double, so adding a run's sum at once gives the same value as adding its cells.
std::vector<RoomCells> roomCells(const cv::Mat& labels, const cv::Mat& depth) {
    std::vector<RoomCells> acc;
    for (int r = 0; r < labels.rows; ++r) {
        const int* row = labels.ptr<int>(r);
        const float* d = depth.ptr<float>(r);
        for (int c = 0; c < labels.cols;) {
            const int id = row[c];
            const int start = c;
            c = detail::runEnd(row, start, labels.cols);
            if (id <= 0)
                continue;
            if (static_cast<std::size_t>(id) > acc.size())
                acc.resize(static_cast<std::size_t>(id));
            RoomCells& a = acc[static_cast<std::size_t>(id - 1)];
            const auto length = static_cast<long long>(c - start);
            a.cells += static_cast<std::size_t>(length);
            a.sumCol += static_cast<double>(length * (start + c - 1) / 2);
            a.sumRow += static_cast<double>(length * r);
            a.minCol = std::min(a.minCol, start);
            a.maxCol = std::max(a.maxCol, c - 1);
            a.minRow = std::min(a.minRow, r);
            a.maxRow = std::max(a.maxRow, r);
            // The run's deepest cell, the first of its greatest depth; it is the room's if deeper
            // than every cell before.
            int k = start;
            float deepest = a.deepest;
            cv::v_float32x4 deepest4 = cv::v_setall_f32(deepest);
            for (; k + 4 <= c; k += 4)
                deepest4 = cv::v_max(deepest4, cv::v_load(d + k));
            deepest = std::max(deepest, cv::v_reduce_max(deepest4));
            for (; k < c; ++k)
                deepest = std::max(deepest, d[k]);
            if (deepest > a.deepest) {
                k = start;
                while (d[k] != deepest)
                    ++k;
                a.deepest = deepest;
                a.anchor = {k, r};
            }
        }
    }
    return acc;
}

// The cells of room `id` in `box` of `labels` as 255 with a ring of zeros around them, written
// into the top-left corner of `buffer` (reused from room to room).
cv::Mat roomMask(const cv::Mat& labels, int id, const cv::Rect& box, cv::Mat& buffer) {
    cv::Mat mask = buffer(cv::Rect(0, 0, box.width + 2, box.height + 2));
    mask.row(0).setTo(0);
    mask.row(mask.rows - 1).setTo(0);
    mask.col(0).setTo(0);
    mask.col(mask.cols - 1).setTo(0);
    cv::Mat inside = mask(cv::Rect(1, 1, box.width, box.height));
    cv::compare(labels(box), id, inside, cv::CMP_EQ);  // same size and type: into the mask
    CV_Assert(inside.data == mask.ptr<std::uint8_t>(1) + 1);
    return mask;
}

}  // namespace

TopologicalMap TopologicalMap::fromLabels(const GridImageFrame& frame, const cv::Mat& labels,
                                          const cv::Mat& clearance) {
    CV_Assert(labels.type() == CV_32S && labels.rows == frame.rows && labels.cols == frame.cols);
    CV_Assert(clearance.empty() ||
              (clearance.type() == CV_32F && clearance.size() == labels.size()));
    TopologicalMap map;
    map.frame = frame;
    map.labels = labels;
    cv::Mat depth = clearance;
    if (depth.empty())
        cv::distanceTransform(labels > 0, depth, cv::DIST_L2, cv::DIST_MASK_5);
    const std::vector<RoomCells> acc = roomCells(labels, depth);
    cv::Mat buffer(labels.rows + 2, labels.cols + 2, CV_8U);
    std::vector<std::vector<cv::Point>> contours;
    for (std::size_t i = 0; i < acc.size(); ++i) {
        const RoomCells& a = acc[i];
        if (a.cells == 0) {
            throw std::invalid_argument(
                "TopologicalMap::fromLabels: room ids must be 1..N without gaps");
        }
        Room room;
        room.id = static_cast<int>(i) + 1;
        room.area = static_cast<double>(a.cells) * frame.cellArea();
        room.centroid = frame.toWorld(a.sumCol / static_cast<double>(a.cells),
                                      a.sumRow / static_cast<double>(a.cells));
        room.anchor = frame.toWorld(a.anchor.x, a.anchor.y);
        // The room's cells in its bounding box plus a ring of zeros.
        const cv::Rect box(a.minCol, a.minRow, a.maxCol - a.minCol + 1, a.maxRow - a.minRow + 1);
        cv::findContours(roomMask(labels, room.id, box, buffer), contours, cv::RETR_EXTERNAL,
                         cv::CHAIN_APPROX_SIMPLE);
        std::size_t largest = 0;
        double largestArea = -1;
        for (std::size_t k = 0; k < contours.size(); ++k) {
            const double area = cv::contourArea(contours[k]);
            if (area > largestArea) {
                largestArea = area;
                largest = k;
            }
        }
        if (!contours.empty()) {
            for (const cv::Point& p : contours[largest]) {
                room.outline.push_back(frame.toWorld(p.x - 1 + box.x, p.y - 1 + box.y));
            }
            double twiceArea = 0;  // shoelace, world frame
            for (std::size_t k = 0; k < room.outline.size(); ++k) {
                const auto& p = room.outline[k];
                const auto& q = room.outline[(k + 1) % room.outline.size()];
                twiceArea += p.x * q.y - q.x * p.y;
            }
            if (twiceArea < 0)
                std::reverse(room.outline.begin(), room.outline.end());
        }
        map.rooms.push_back(std::move(room));
    }
    return map;
}

const Room* TopologicalMap::room(int id) const {
    return id >= 1 && id <= static_cast<int>(rooms.size())
               ? &rooms[static_cast<std::size_t>(id - 1)]
               : nullptr;
}

Room* TopologicalMap::room(int id) {
    return id >= 1 && id <= static_cast<int>(rooms.size())
               ? &rooms[static_cast<std::size_t>(id - 1)]
               : nullptr;
}

int TopologicalMap::roomAt(double x, double y) const {
    const cv::Point p = frame.toCell(x, y);
    if (labels.empty() || !frame.contains(p))
        return 0;
    return labels.at<int>(p);
}

std::vector<std::pair<int, int>> TopologicalMap::adjacency() const {
    std::vector<std::pair<int, int>> pairs;
    for (const Door& d : doors)
        pairs.emplace_back(std::min(d.roomA, d.roomB), std::max(d.roomA, d.roomB));
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

std::vector<int> TopologicalMap::neighbours(int id) const {
    std::vector<int> out;
    for (const Door& d : doors) {
        if (d.roomA == id)
            out.push_back(d.roomB);
        if (d.roomB == id)
            out.push_back(d.roomA);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<const Door*> TopologicalMap::doorsBetween(int a, int b) const {
    std::vector<const Door*> out;
    for (const Door& d : doors) {
        if ((d.roomA == a && d.roomB == b) || (d.roomA == b && d.roomB == a))
            out.push_back(&d);
    }
    return out;
}

}  // namespace toposlam::rooms
