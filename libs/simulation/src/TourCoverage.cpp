#include <toposlam/simulation/TourCoverage.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <deque>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

std::vector<std::uint8_t> cellsInView(const ClearanceMap& map,
                                      const std::vector<TPoint2D>& viewpoints, double range) {
    const GridGeometry& g = map.geometry();
    std::vector<std::uint8_t> seen(g.cellCount(), 0);
    // Enough sight lines that neighbouring ones are at most a cell apart at full range; each
    // is walked in half-cell steps, so no cell it crosses is skipped by more than a corner.
    const int lines = std::max(8, static_cast<int>(std::ceil(2 * M_PI * range / g.resolution)));
    std::vector<double> stepX(static_cast<std::size_t>(lines)), stepY(stepX.size());
    const double step = g.resolution / 2;
    for (int k = 0; k < lines; ++k) {
        stepX[static_cast<std::size_t>(k)] = step * std::cos(2 * M_PI * k / lines);
        stepY[static_cast<std::size_t>(k)] = step * std::sin(2 * M_PI * k / lines);
    }
    const int steps = static_cast<int>(std::floor(range / step));
    for (const TPoint2D& p : viewpoints) {
        if (!map.isFree(g.cellX(p.x), g.cellY(p.y)))
            continue;
        for (std::size_t k = 0; k < stepX.size(); ++k) {
            for (int s = 0; s <= steps; ++s) {
                const int cx = g.cellX(p.x + s * stepX[k]), cy = g.cellY(p.y + s * stepY[k]);
                if (!g.contains(cx, cy))
                    break;
                seen[g.index(cx, cy)] = 1;
                if (!map.isFree(cx, cy))
                    break;
            }
        }
    }
    return seen;
}

std::vector<std::uint8_t> cellsInView(const ClearanceMap& map, const io::Trajectory2D& poses,
                                      double range) {
    std::vector<TPoint2D> positions;
    positions.reserve(poses.size());
    for (const auto& p : poses)
        positions.emplace_back(p.pose.x, p.pose.y);
    return cellsInView(map, positions, range);
}

namespace {
/// The reachable cell nearest to the cells labelled `label` (walking 8-connected through free
/// cells, at most maxSteps steps); -1 when there is none. `visited` is scratch, all 0 on entry
/// and on return.
long nearestReachable(const ClearanceMap& map, const cv::Mat& labels, int label,
                      const cv::Rect& box, const std::vector<std::uint8_t>& reachable, int maxSteps,
                      std::vector<int>& visited) {
    const GridGeometry& g = map.geometry();
    std::deque<std::pair<std::size_t, int>> queue;  // cell index, steps from the area
    std::vector<std::size_t> touched;
    for (int y = box.y; y < box.y + box.height; ++y) {
        const int* row = labels.ptr<int>(y);
        for (int x = box.x; x < box.x + box.width; ++x) {
            if (row[x] == label) {
                queue.emplace_back(g.index(x, y), 0);
                visited[g.index(x, y)] = 1;
                touched.push_back(g.index(x, y));
            }
        }
    }
    long found = -1;
    while (!queue.empty() && found < 0) {
        const auto [cell, steps] = queue.front();
        queue.pop_front();
        if (reachable[cell]) {
            found = static_cast<long>(cell);
            break;
        }
        if (steps == maxSteps)
            continue;
        const int cx = static_cast<int>(cell % static_cast<std::size_t>(g.sizeX));
        const int cy = static_cast<int>(cell / static_cast<std::size_t>(g.sizeX));
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = cx + dx, ny = cy + dy;
                if ((dx == 0 && dy == 0) || !map.isFree(nx, ny))
                    continue;
                const std::size_t n = g.index(nx, ny);
                if (visited[n])
                    continue;
                visited[n] = 1;
                touched.push_back(n);
                queue.emplace_back(n, steps + 1);
            }
        }
    }
    for (std::size_t cell : touched)
        visited[cell] = 0;
    return found;
}
}  // namespace

std::vector<UnseenArea> findUnseenAreas(const ClearanceMap& map,
                                        const std::vector<std::uint8_t>& seen,
                                        const std::vector<std::uint8_t>& reachable,
                                        const TourCoverageOptions& options) {
    const GridGeometry& g = map.geometry();
    // Rows of the image are the grid's cy, columns its cx: the layout of GridGeometry::index.
    cv::Mat unseen(g.sizeY, g.sizeX, CV_8U, cv::Scalar(0));
    for (int cy = 0; cy < g.sizeY; ++cy) {
        auto* row = unseen.ptr<std::uint8_t>(cy);
        for (int cx = 0; cx < g.sizeX; ++cx)
            row[cx] = map.isFree(cx, cy) && !seen[g.index(cx, cy)] ? 255 : 0;
    }
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(unseen, labels, stats, centroids, 8, CV_32S);
    const double cellArea = g.resolution * g.resolution;
    const int maxSteps = static_cast<int>(std::ceil(options.viewRange / g.resolution));
    std::vector<int> visited(g.cellCount(), 0);
    std::vector<UnseenArea> areas;
    for (int label = 1; label < n; ++label) {
        UnseenArea area;
        area.areaM2 = stats.at<int>(label, cv::CC_STAT_AREA) * cellArea;
        if (area.areaM2 < options.minUnseenAreaM2)
            continue;
        area.centroid = TPoint2D(g.xMin + (centroids.at<double>(label, 0) + 0.5) * g.resolution,
                                 g.yMin + (centroids.at<double>(label, 1) + 0.5) * g.resolution);
        const cv::Rect box(
            stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
            stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
        const long cell = nearestReachable(map, labels, label, box, reachable, maxSteps, visited);
        if (cell >= 0) {
            area.hasViewpoint = true;
            area.viewpoint = g.centre(static_cast<std::size_t>(cell));
        }
        areas.push_back(area);
    }
    std::stable_sort(areas.begin(), areas.end(),
                     [](const UnseenArea& a, const UnseenArea& b) { return a.areaM2 > b.areaM2; });
    return areas;
}

}  // namespace toposlam::simulation
