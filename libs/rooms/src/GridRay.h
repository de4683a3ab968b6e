#pragma once
// Walking a ray over the cells of a binary image (internal to libs/rooms).
#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace toposlam::rooms::detail {

/// Metres as a number of cells. Grids store their resolution as a float (0.05 becomes
/// 0.0500000007), so a length that is a whole number of cells is snapped to it: 0.6 m at 5 cm
/// is 12 cells, not 11.99999983, and comparisons against integer cell distances stay exact.
inline double toCells(double metres, double resolution) {
    const double cells = metres / resolution;
    const double whole = std::round(cells);
    return std::abs(cells - whole) < 1e-6 * std::max(1.0, std::abs(cells)) ? whole : cells;
}

/// std::hypot(dx, dy) of a whole-cell offset (the same value: below 128 cells each way it is
/// looked up in a table of std::hypot's results, farther it is computed).
inline double cellDistance(int dx, int dy) {
    constexpr int kSide = 128;
    static const std::vector<double> table = [] {
        std::vector<double> t(static_cast<std::size_t>(kSide) * kSide);
        for (int y = 0; y < kSide; ++y) {
            for (int x = 0; x < kSide; ++x)
                t[static_cast<std::size_t>(y) * kSide + static_cast<std::size_t>(x)] =
                    std::hypot(x, y);
        }
        return t;
    }();
    const int ax = std::abs(dx), ay = std::abs(dy);
    if (ax < kSide && ay < kSide)
        return table[static_cast<std::size_t>(ay) * kSide + static_cast<std::size_t>(ax)];
    return std::hypot(dx, dy);
}

/// True when (x, y) is inside `mask` and non-zero.
inline bool isSet(const cv::Mat& mask, int x, int y) {
    return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<std::uint8_t>(y, x) != 0;
}

/// Walks from the centre of `from` along (ux, uy) (unit vector, pixels) over every cell the ray
/// touches, in order, and returns the first cell for which `stop(x, y, t)` is true and that lies
/// within `maxDistance` pixels of the start (t: the ray parameter where it enters the cell;
/// never above maxDistance). Where the ray passes exactly through a cell corner, both side
/// cells are tested first, so a diagonal (8-connected) line of stop cells cannot be slipped
/// through.
template <class Stop>
bool walkRayEntries(const cv::Point& from, double ux, double uy, double maxDistance, Stop stop,
                    cv::Point& hit) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    int x = from.x, y = from.y;
    const int stepX = ux > 0 ? 1 : (ux < 0 ? -1 : 0);
    const int stepY = uy > 0 ? 1 : (uy < 0 ? -1 : 0);
    const double deltaX = stepX != 0 ? 1.0 / std::abs(ux) : inf;
    const double deltaY = stepY != 0 ? 1.0 / std::abs(uy) : inf;
    double nextX = 0.5 * deltaX, nextY = 0.5 * deltaY;  // ray parameter at the next cell edges
    while (true) {
        double t = 0;
        if (std::abs(nextX - nextY) < 1e-9) {
            t = nextX;
            if (t > maxDistance)
                return false;
            if (stop(x + stepX, y, t)) {
                hit = {x + stepX, y};
                return true;
            }
            if (stop(x, y + stepY, t)) {
                hit = {x, y + stepY};
                return true;
            }
            x += stepX;
            y += stepY;
            nextX += deltaX;
            nextY += deltaY;
        } else if (nextX < nextY) {
            t = nextX;
            x += stepX;
            nextX += deltaX;
        } else {
            t = nextY;
            y += stepY;
            nextY += deltaY;
        }
        if (t > maxDistance)
            return false;
        if (stop(x, y, t)) {
            hit = {x, y};
            return true;
        }
    }
}

/// walkRayEntries() with `stop(x, y)`.
template <class Stop>
bool walkRay(const cv::Point& from, double ux, double uy, double maxDistance, Stop stop,
             cv::Point& hit) {
    return walkRayEntries(
        from, ux, uy, maxDistance, [&](int x, int y, double) { return stop(x, y); }, hit);
}

/// How far (ray parameter, pixels) the ray from `from` in direction -(ux, uy) needs to be
/// walked to find the other end of a cut whose one end is `near` (found along (ux, uy)), when
/// only cuts shorter than `maxLength` count: any cell the ray enters farther out lies more
/// than maxLength from `near` (a cell's centre is within sqrt(1/2) of where the ray enters
/// it, so |near - far| >= (near - from).u + t - sqrt(1/2); 0.01 px spare for rounding).
inline double farSideReach(const cv::Point& from, const cv::Point& near, double ux, double uy,
                           double maxLength) {
    const double along = (near.x - from.x) * ux + (near.y - from.y) * uy;
    return maxLength + std::sqrt(0.5) - along + 0.01;
}

/// Whether every cell within `margin` cells of `p` (along x and along y) lies inside `image`.
inline bool isInterior(const cv::Mat& image, const cv::Point& p, double margin) {
    if (!(margin < static_cast<double>(std::min(image.cols, image.rows))))
        return false;
    const int m = static_cast<int>(std::ceil(margin));
    return p.x >= m && p.y >= m && p.x + m < image.cols && p.y + m < image.rows;
}

/// Reads the cells of a CV_8U mask: true when non-zero. `Checked`: cells outside read as
/// false; unchecked reads are for cells known to be inside (isInterior).
template <bool Checked>
class MaskReader {
  public:
    explicit MaskReader(const cv::Mat& mask) : data_(mask.data), step_(mask.step[0]) {
        if constexpr (Checked) {
            cols_ = mask.cols;
            rows_ = mask.rows;
        }
    }
    bool operator()(int x, int y) const {
        if constexpr (Checked) {
            if (x < 0 || y < 0 || x >= cols_ || y >= rows_)
                return false;
        }
        return data_[static_cast<std::ptrdiff_t>(y) * static_cast<std::ptrdiff_t>(step_) + x] != 0;
    }

  private:
    const std::uint8_t* data_;
    std::size_t step_;
    int cols_ = 0, rows_ = 0;
};

/// `walk(reader)` with a MaskReader of `mask`: unchecked when every cell within `reach` of
/// `around` is inside the mask (a ray of length `reach - 1` from there, and its 8-neighbours,
/// cannot leave it), checked otherwise. Both read the same values, so the result is the same.
template <class Walk>
bool withMaskReader(const cv::Mat& mask, const cv::Point& around, double reach, Walk&& walk) {
    if (isInterior(mask, around, reach))
        return walk(MaskReader<false>(mask));
    return walk(MaskReader<true>(mask));
}

/// The cells walkRay() visits along one direction, as offsets from the start cell, in order:
/// the ray's cells do not depend on where it starts (always at a cell centre), so a direction
/// used from many cells is walked once. Bound to the row step of one mask.
class RayPattern {
  public:
    RayPattern() = default;
    /// The cells within `maxDistance` pixels along (ux, uy), offsets for rows of `mask`.
    RayPattern(double ux, double uy, double maxDistance, const cv::Mat& mask) {
        cv::Point unused;
        // With each cell its ray parameter at entry: walked with a shorter maxDistance, the
        // ray visits the cells up to the first that it enters beyond that.
        walkRayEntries(
            {0, 0}, ux, uy, maxDistance,
            [&](int x, int y, double t) {
                cells_.emplace_back(x, y);
                entries_.push_back(t);
                return false;
            },
            unused);
        offsets_.reserve(cells_.size());
        boxes_.reserve(cells_.size());
        for (const cv::Point& c : cells_) {
            Box box{c, c};
            if (!boxes_.empty()) {
                box.low = {std::min(c.x, boxes_.back().low.x), std::min(c.y, boxes_.back().low.y)};
                box.high = {std::max(c.x, boxes_.back().high.x),
                            std::max(c.y, boxes_.back().high.y)};
            }
            boxes_.push_back(box);
            reach_ = std::max({reach_, std::abs(c.x), std::abs(c.y)});
            offsets_.push_back(
                static_cast<std::ptrdiff_t>(c.y) * static_cast<std::ptrdiff_t>(mask.step[0]) + c.x);
        }
    }

    /// walkRay(from, ux, uy, maxDistance, stop = "not set in `mask`", hit), outside the mask
    /// counting as not set: the first cell of the ray from `from` that is not set. `mask`:
    /// CV_8U, the row step the pattern was made for.
    bool firstUnset(const cv::Mat& mask, const cv::Point& from, cv::Point& hit) const {
        return firstUnset(mask, from, hit, cells_.size());
    }
    /// The same, walked only as far as `maxDistance` (at most the pattern's).
    bool firstUnset(const cv::Mat& mask, const cv::Point& from, double maxDistance,
                    cv::Point& hit) const {
        const auto within = std::upper_bound(entries_.begin(), entries_.end(), maxDistance);
        return firstUnset(mask, from, hit, static_cast<std::size_t>(within - entries_.begin()));
    }

  private:
    // The first `count` cells of the pattern.
    bool firstUnset(const cv::Mat& mask, const cv::Point& from, cv::Point& hit,
                    std::size_t count) const {
        const cv::Rect image(0, 0, mask.cols, mask.rows);
        if (image.contains(from)) {
            // Near the border: the cells before the first one outside the mask, found by
            // bisection on the boxes of the first cells (inside while the box is), are read
            // unchecked; the first one outside is not set.
            std::size_t inside = count;
            if (!isInterior(mask, from, reach_)) {
                inside = static_cast<std::size_t>(
                    std::partition_point(boxes_.begin(),
                                         boxes_.begin() + static_cast<std::ptrdiff_t>(count),
                                         [&](const Box& box) {
                                             return image.contains(from + box.low) &&
                                                    image.contains(from + box.high);
                                         }) -
                    boxes_.begin());
            }
            const std::uint8_t* start = mask.ptr<std::uint8_t>(from.y) + from.x;
            for (std::size_t k = 0; k < inside; ++k) {
                if (start[offsets_[k]] == 0) {
                    hit = from + cells_[k];
                    return true;
                }
            }
            if (inside == count)
                return false;
            hit = from + cells_[inside];
            return true;
        }
        for (std::size_t k = 0; k < count; ++k) {
            if (!isSet(mask, from.x + cells_[k].x, from.y + cells_[k].y)) {
                hit = from + cells_[k];
                return true;
            }
        }
        return false;
    }

    std::vector<cv::Point> cells_;
    std::vector<double> entries_;  // ray parameter where each cell is entered (non-decreasing)
    std::vector<std::ptrdiff_t> offsets_;
    struct Box {
        cv::Point low, high;  // the lowest and highest x and y
    };
    std::vector<Box> boxes_;  // [k]: the box of cells 0..k
    int reach_ = 0;
};

}  // namespace toposlam::rooms::detail
