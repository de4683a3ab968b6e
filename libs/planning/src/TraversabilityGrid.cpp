#include <toposlam/planning/TraversabilityGrid.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace toposlam::planning {

TraversabilityGrid::TraversabilityGrid(const mrpt::maps::COccupancyGridMap2D& grid,
                                       double robotRadius, double freeThreshold)
    : robotRadius_(robotRadius) {
    frame_.resolution = grid.getResolution();
    frame_.xMin = grid.getXMin();
    frame_.yMin = grid.getYMin();
    frame_.cols = static_cast<int>(grid.getSizeX());
    frame_.rows = static_cast<int>(grid.getSizeY());

    // Free cells, with a one-cell obstacle border: beyond the map is unknown, never free.
    cv::Mat free(frame_.rows + 2, frame_.cols + 2, CV_8U, cv::Scalar(0));
    const auto& raw = grid.getRawMap();  // log-odds, row-major from cy = 0 (smallest y)
    const auto freeLogOdds =
        mrpt::maps::COccupancyGridMap2D::p2l(static_cast<float>(freeThreshold));
    for (int cy = 0; cy < frame_.rows; ++cy) {
        auto* row = free.ptr<std::uint8_t>(frame_.rows - cy);  // image row = rows-1-cy, +1 border
        const auto* cells =
            &raw[static_cast<std::size_t>(cy) * static_cast<std::size_t>(frame_.cols)];
        for (int cx = 0; cx < frame_.cols; ++cx)
            row[cx + 1] = cells[cx] > freeLogOdds ? 255 : 0;
    }
    cv::Mat distance;  // pixels, centre to the centre of the nearest obstacle cell
    cv::distanceTransform(free, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    const cv::Rect inner(1, 1, frame_.cols, frame_.rows);
    const auto res = static_cast<float>(frame_.resolution);
    // Clearance to the obstacle cell's boundary, not its centre: half a cell less.
    clearanceM_ = cv::max(distance(inner) * res - 0.5f * res, 0.0f);
    traversable_ = clearanceM_ >= static_cast<float>(robotRadius);  // 255 where true
    traversable_ &= free(inner);
}

double TraversabilityGrid::clearance(double x, double y) const {
    const cv::Point c = frame_.toCell(x, y);
    return frame_.contains(c) ? clearanceM_.at<float>(c) : 0.0;
}

bool TraversabilityGrid::isSegmentTraversable(const mrpt::math::TPoint2D& a,
                                              const mrpt::math::TPoint2D& b) const {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = std::max(1, static_cast<int>(std::ceil(4.0 * length / frame_.resolution)));
    for (int k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        if (!isTraversable(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)))
            return false;
    }
    return true;
}

std::optional<mrpt::math::TPoint2D> TraversabilityGrid::nearestTraversable(
    const mrpt::math::TPoint2D& p, double maxDistance) const {
    const cv::Point centre = frame_.toCell(p.x, p.y);
    const int reach = static_cast<int>(std::ceil(maxDistance / frame_.resolution));
    std::optional<mrpt::math::TPoint2D> best;
    double bestDist = maxDistance;
    for (int r = std::max(0, centre.y - reach); r <= std::min(frame_.rows - 1, centre.y + reach);
         ++r) {
        for (int c = std::max(0, centre.x - reach);
             c <= std::min(frame_.cols - 1, centre.x + reach); ++c) {
            if (!traversable_.at<std::uint8_t>(r, c))
                continue;
            const mrpt::math::TPoint2D w = frame_.toWorld(c, r);
            const double d = std::hypot(w.x - p.x, w.y - p.y);
            if (d <= bestDist) {
                bestDist = d;
                best = w;
            }
        }
    }
    return best;
}

}  // namespace toposlam::planning
