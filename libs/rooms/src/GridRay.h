#pragma once
// Walking a ray over the cells of a binary image (internal to libs/rooms).
#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace toposlam::rooms::detail {

/// Metres as a number of cells. Grids store their resolution as a float (0.05 becomes
/// 0.0500000007), so a length that is a whole number of cells is snapped to it: 0.6 m at 5 cm
/// is 12 cells, not 11.99999983, and comparisons against integer cell distances stay exact.
inline double toCells(double metres, double resolution) {
    const double cells = metres / resolution;
    const double whole = std::round(cells);
    return std::abs(cells - whole) < 1e-6 * std::max(1.0, std::abs(cells)) ? whole : cells;
}

/// True when (x, y) is inside `mask` and non-zero.
inline bool isSet(const cv::Mat& mask, int x, int y) {
    return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<std::uint8_t>(y, x) != 0;
}

/// Walks from the centre of `from` along (ux, uy) (unit vector, pixels) over every cell the ray
/// touches, in order, and returns the first cell for which `stop(x, y)` is true and that lies
/// within `maxDistance` pixels of the start (ray parameter at cell entry). Where the ray passes
/// exactly through a cell corner, both side cells are tested first, so a diagonal (8-connected)
/// line of stop cells cannot be slipped through.
template <class Stop>
bool walkRay(const cv::Point& from, double ux, double uy, double maxDistance, Stop stop,
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
            if (stop(x + stepX, y)) {
                hit = {x + stepX, y};
                return true;
            }
            if (stop(x, y + stepY)) {
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
        if (stop(x, y)) {
            hit = {x, y};
            return true;
        }
    }
}

}  // namespace toposlam::rooms::detail
