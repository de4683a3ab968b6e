#include <toposlam/rooms/FurniturePockets.h>

#include "GridRay.h"
#include "LabelRuns.h"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace toposlam::rooms {

namespace {

/// Cell `p` in the main directions' frame (cells): x along the main direction, y across it.
cv::Point2d inMainFrame(const cv::Point& p, double cosine, double sine) {
    return {p.x * cosine + p.y * sine, p.y * cosine - p.x * sine};
}

/// The lines of `histogram` (1-cell bins from `origin`) from the first to the last full one, as
/// the interval [lo, hi) of the axis; empty (hi <= lo) when there is none. A full line holds at
/// least `minCount` cells and at least half as many as the line two cells further in: a wall
/// drawn at an angle ends in steps, and the lines through their tips hold a part of a line.
void trimToFullLines(const std::vector<int>& histogram, double minCount, double origin, double& lo,
                     double& hi) {
    const std::size_t n = histogram.size();
    auto full = [&](std::size_t line, std::size_t inner) {
        return histogram[line] >= minCount &&
               (inner >= n || 2 * histogram[line] >= histogram[inner]);
    };
    std::size_t first = 0, end = n;
    while (first < end && !full(first, first + 2))
        ++first;
    while (end > first && !full(end - 1, end >= 3 ? end - 3 : n))
        --end;
    lo = origin + static_cast<double>(first);
    hi = origin + static_cast<double>(end);
}

/// Calls found(k) for each unlabelled (0) cell of row[begin, end), in order; four cells at a
/// time: next to a room's run most cells are the room's.
template <class Found>
void forEachUnlabelled(const int* row, int begin, int end, Found found) {
    const cv::v_int32x4 zero = cv::v_setzero_s32();
    for (int k = begin; k < end;) {
        if (k + 4 <= end && !cv::v_check_any(cv::v_load(row + k) == zero)) {
            k += 4;
            continue;
        }
        if (row[k] == 0)
            found(k);
        ++k;
    }
}

}  // namespace

void FurniturePockets::measureBoxes(double cosine, double sine, double minSideCells,
                                    const cv::Mat& labels) {
    // u runs along the main direction, v across it; bins of one cell from the image's lowest u
    // and v, so that one pass measures every room.
    const double uOrigin =
        std::min(0.0, cosine * (labels.cols - 1)) + std::min(0.0, sine * (labels.rows - 1));
    const double vOrigin =
        std::min(0.0, cosine * (labels.rows - 1)) + std::min(0.0, -sine * (labels.cols - 1));
    const auto uBins = static_cast<std::size_t>(std::abs(cosine) * (labels.cols - 1) +
                                                std::abs(sine) * (labels.rows - 1) + 2);
    const auto vBins = static_cast<std::size_t>(std::abs(cosine) * (labels.rows - 1) +
                                                std::abs(sine) * (labels.cols - 1) + 2);
    for (RoomBox& b : boxes_)
        b.seen = false;
    auto box = [&](int label) -> RoomBox& {
        const auto id = static_cast<std::size_t>(label);
        if (id >= boxes_.size())
            boxes_.resize(id + 1);
        RoomBox& b = boxes_[id];
        if (!b.seen) {
            b.seen = true;
            b.measured = false;
            b.alongU.assign(uBins, 0);
            b.alongV.assign(vBins, 0);
            b.seeds.clear();
        }
        return b;
    };
    // Lines are counted in fixed point (1/65536 cell): over a row the rounding of the step adds
    // up to a few hundredths of a cell.
    constexpr double kFixed = 65536.0;
    const auto uStep = static_cast<std::int64_t>(std::llround(cosine * kFixed));
    const auto vStep = static_cast<std::int64_t>(std::llround(-sine * kFixed));
    const auto uLast = static_cast<std::int64_t>(uBins - 1),
               vLast = static_cast<std::int64_t>(vBins - 1);
    // Rows in runs of one label.
    for (int y = 0; y < labels.rows; ++y) {
        const int* row = labels.ptr<int>(y);
        const auto* door = nearDoor_.ptr<std::uint8_t>(y);
        for (int x = 0; x < labels.cols;) {
            const int x0 = x, label = row[x0];
            x = detail::runEnd(row, x0, labels.cols);
            if (label <= 0)
                continue;
            RoomBox& b = box(label);
            // The unlabelled 4-neighbours of the room, where its pockets start.
            if (x0 > 0 && row[x0 - 1] == 0)
                b.seeds.emplace_back(x0 - 1, y);
            if (x < labels.cols && row[x] == 0)
                b.seeds.emplace_back(x, y);
            for (const int ny : {y - 1, y + 1}) {
                if (ny < 0 || ny >= labels.rows)
                    continue;
                forEachUnlabelled(labels.ptr<int>(ny), x0, x,
                                  [&](int k) { b.seeds.emplace_back(k, ny); });
            }
            // How many of the room's cells each line across it holds; not counting the cells
            // near a door (the room's half of a door opening reaches into the wall).
            const cv::Point2d start = inMainFrame({x0, y}, cosine, sine);
            auto u = static_cast<std::int64_t>(std::llround((start.x - uOrigin) * kFixed));
            auto v = static_cast<std::int64_t>(std::llround((start.y - vOrigin) * kFixed));
            int* alongU = b.alongU.data();
            int* alongV = b.alongV.data();
            for (int k = x0; k < x; ++k, u += uStep, v += vStep) {
                if (door[k] != 0)
                    continue;
                // Clamped: the running sums may stray past the image by their rounding.
                ++alongU[std::clamp<std::int64_t>(u >> 16, 0, uLast)];
                ++alongV[std::clamp<std::int64_t>(v >> 16, 0, vLast)];
            }
            b.measured = true;
        }
    }
    // The box: from the first to the last full line, one cell in from each side; half-open.
    for (RoomBox& b : boxes_) {
        if (!b.seen || !b.measured)
            continue;
        trimToFullLines(b.alongU, minSideCells, uOrigin, b.u0, b.u1);
        trimToFullLines(b.alongV, minSideCells, vOrigin, b.v0, b.v1);
        b.u0 += 1, b.u1 -= 1, b.v0 += 1, b.v1 -= 1;
    }
}

std::size_t FurniturePockets::label(const Options& options, double mainDirection,
                                    const std::vector<VirtualDoor>& doors, double resolution,
                                    cv::Mat& labels) {
    CV_Assert(labels.type() == CV_32S);
    if (!(options.maxSize > 0) || labels.empty())
        return 0;
    const double cosine = std::cos(mainDirection), sine = std::sin(mainDirection);
    const double maxSize = detail::toCells(options.maxSize, resolution);
    nearDoor_.create(labels.size(), CV_8U);
    nearDoor_.setTo(0);
    for (const VirtualDoor& d : doors) {
        const double reach = 0.5 * d.width + detail::toCells(options.doorReach, resolution);
        cv::circle(nearDoor_, (d.jambA + d.jambB) / 2, static_cast<int>(std::ceil(reach)),
                   cv::Scalar(255), cv::FILLED);
    }
    measureBoxes(cosine, sine, detail::toCells(options.minSide, resolution), labels);

    // Each flood gets its own number in visited_. A flood that grows beyond maxSize or reaches
    // another room stops where it is; a later flood of the same room that reaches its cells is
    // in the same (no pocket) component and stops too, so no cell is walked twice per room.
    // Pockets are marked -room until every room is done: a pocket next to another room's
    // pocket is no pocket of either (a wall between two rooms' furniture).
    visited_.create(labels.size(), CV_32S);
    visited_.setTo(0);
    int flood = 0;
    const cv::Rect image(0, 0, labels.cols, labels.rows);
    const cv::Point around[8] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1},
                                 {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    filled_.clear();
    for (std::size_t id = 1; id < boxes_.size(); ++id) {
        const RoomBox& b = boxes_[id];
        if (!b.seen || !b.measured || b.u1 <= b.u0 || b.v1 <= b.v0)
            continue;
        const int room = static_cast<int>(id);
        const int firstFlood = flood + 1;
        auto inBox = [&](const cv::Point& p) {
            const cv::Point2d q = inMainFrame(p, cosine, sine);
            return q.x >= b.u0 && q.x < b.u1 && q.y >= b.v0 && q.y < b.v1;
        };
        for (const cv::Point& seed : b.seeds) {
            if (labels.at<int>(seed) != 0 || visited_.at<int>(seed) >= firstFlood || !inBox(seed))
                continue;
            ++flood;
            visited_.at<int>(seed) = flood;
            stack_.assign(1, seed);
            pocket_.clear();
            bool isPocket = true;
            double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
            while (!stack_.empty() && isPocket) {
                const cv::Point p = stack_.back();
                stack_.pop_back();
                const cv::Point2d q = inMainFrame(p, cosine, sine);
                const double u = q.x, v = q.y;
                if (pocket_.empty())
                    u0 = u1 = u, v0 = v1 = v;
                u0 = std::min(u0, u), u1 = std::max(u1, u);
                v0 = std::min(v0, v), v1 = std::max(v1, v);
                pocket_.push_back(p);
                if (u1 - u0 > maxSize || v1 - v0 > maxSize) {
                    isPocket = false;
                    break;
                }
                for (const cv::Point& o : around) {
                    const cv::Point q = p + o;
                    if (!image.contains(q))
                        continue;
                    const int l = labels.at<int>(q);
                    if (l == room)
                        continue;
                    const int seen = visited_.at<int>(q);
                    if (l != 0 || (seen >= firstFlood && seen != flood)) {
                        isPocket = false;  // another room (or its pocket), or a stopped flood
                        break;
                    }
                    if (seen != flood && inBox(q)) {
                        visited_.at<int>(q) = flood;
                        stack_.push_back(q);
                    }
                }
            }
            // Furniture is rectangular: a pocket fills at least half its own box.
            if (!isPocket ||
                2.0 * static_cast<double>(pocket_.size()) < (u1 - u0 + 1) * (v1 - v0 + 1))
                continue;
            for (const cv::Point& p : pocket_)
                labels.at<int>(p) = -room;
            filled_.insert(filled_.end(), pocket_.begin(), pocket_.end());
        }
    }
    for (const cv::Point& p : filled_)
        labels.at<int>(p) = -labels.at<int>(p);
    return filled_.size();
}

}  // namespace toposlam::rooms
