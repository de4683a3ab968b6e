#include <toposlam/simulation/TourCoverage.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <deque>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

namespace {
/// Unit sight-line steps (half a cell long) in every direction, enough lines that neighbouring
/// ones are at most a cell apart at full range.
struct SightLines {
    SightLines(const GridGeometry& g, double range) {
        const int lines = std::max(8, static_cast<int>(std::ceil(2 * M_PI * range / g.resolution)));
        const double step = g.resolution / 2;
        for (int k = 0; k < lines; ++k) {
            stepX.push_back(step * std::cos(2 * M_PI * k / lines));
            stepY.push_back(step * std::sin(2 * M_PI * k / lines));
        }
        steps = static_cast<int>(std::floor(range / step));
    }
    std::vector<double> stepX, stepY;
    int steps = 0;
};

/// Calls visit(cell index) for every cell in line of sight of `p` (through free cells, the
/// first non-free cell of each line included); a cell may be visited more than once.
template <typename Visit>
void forEachInView(const ClearanceMap& map, const SightLines& lines, const TPoint2D& p,
                   Visit&& visit) {
    const GridGeometry& g = map.geometry();
    if (!map.isFree(g.cellX(p.x), g.cellY(p.y)))
        return;
    for (std::size_t k = 0; k < lines.stepX.size(); ++k) {
        for (int s = 0; s <= lines.steps; ++s) {
            const int cx = g.cellX(p.x + s * lines.stepX[k]),
                      cy = g.cellY(p.y + s * lines.stepY[k]);
            if (!g.contains(cx, cy))
                break;
            visit(g.index(cx, cy));
            if (!map.isFree(cx, cy))
                break;
        }
    }
}
}  // namespace

std::vector<std::uint8_t> cellsInView(const ClearanceMap& map,
                                      const std::vector<TPoint2D>& viewpoints, double range) {
    std::vector<std::uint8_t> seen(map.geometry().cellCount(), 0);
    // Each line is walked in half-cell steps, so no cell it crosses is skipped by more than a
    // corner.
    const SightLines lines(map.geometry(), range);
    for (const TPoint2D& p : viewpoints)
        forEachInView(map, lines, p, [&](std::size_t cell) { seen[cell] = 1; });
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
/// Most stops for one unseen area (a whole wing the room-sized tour did not enter).
constexpr std::size_t kMaxStopsPerArea = 256;

/// The reachable cell nearest to `cells` (walking 8-connected through free cells, at most
/// maxSteps steps); -1 when there is none. `visited` is scratch, all 0 on entry and on return.
long nearestReachable(const ClearanceMap& map, const std::vector<std::size_t>& cells,
                      const std::vector<std::uint8_t>& reachable, int maxSteps,
                      std::vector<int>& visited) {
    const GridGeometry& g = map.geometry();
    std::deque<std::pair<std::size_t, int>> queue;  // cell index, steps from the area
    std::vector<std::size_t> touched;
    for (std::size_t cell : cells) {
        queue.emplace_back(cell, 0);
        visited[cell] = 1;
        touched.push_back(cell);
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

/// The reachable cell of `cells` farthest from any obstacle (the middle of the widest room the
/// area holds); -1 when none is reachable.
long widestReachable(const ClearanceMap& map, const std::vector<std::size_t>& cells,
                     const std::vector<std::uint8_t>& reachable) {
    long best = -1;
    float widest = -1;
    for (std::size_t cell : cells) {
        const float c = map.clearances()[cell];
        if (reachable[cell] && c > widest) {
            widest = c;
            best = static_cast<long>(cell);
        }
    }
    return best;
}
}  // namespace

std::vector<UnseenArea> findUnseenAreas(const ClearanceMap& map,
                                        const std::vector<std::uint8_t>& seen,
                                        const std::vector<std::uint8_t>& reachable,
                                        const TourCoverageOptions& options,
                                        bool skipOpenToMapEdge) {
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
    const auto minCells = static_cast<std::size_t>(std::ceil(options.minUnseenAreaM2 / cellArea));
    const int maxSteps = static_cast<int>(std::ceil(options.viewRange / g.resolution));
    const SightLines lines(g, options.viewRange);
    std::vector<int> visited(g.cellCount(), 0);
    // Cells in view of the stops chosen so far (for every area: a stop sees what it sees).
    std::vector<std::uint8_t> inView(g.cellCount(), 0);
    std::vector<std::size_t> left;  // the cells of the area no stop sees yet
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
        // The box's extremes are cells of the area: a box on the map's edge is an area on it.
        if (skipOpenToMapEdge && (box.x == 0 || box.y == 0 || box.x + box.width == g.sizeX ||
                                  box.y + box.height == g.sizeY)) {
            continue;
        }
        left.clear();
        for (int y = box.y; y < box.y + box.height; ++y) {
            const int* row = labels.ptr<int>(y);
            for (int x = box.x; x < box.x + box.width; ++x) {
                const std::size_t cell = g.index(x, y);
                if (row[x] == label && !inView[cell])
                    left.push_back(cell);
            }
        }
        // Stops until what the area still hides is too small to matter: a closet is seen from
        // its doorway; a wing the tour did not enter needs a stop in each of its rooms, the
        // widest first.
        while (left.size() >= minCells && area.viewpoints.size() < kMaxStopsPerArea) {
            long stop = widestReachable(map, left, reachable);
            if (stop < 0)
                stop = nearestReachable(map, left, reachable, maxSteps, visited);
            if (stop < 0)
                break;
            const TPoint2D p = g.centre(static_cast<std::size_t>(stop));
            forEachInView(map, lines, p, [&](std::size_t cell) { inView[cell] = 1; });
            inView[static_cast<std::size_t>(stop)] = 1;  // even if nothing is seen from it
            const std::size_t hidden = left.size();
            left.erase(std::remove_if(left.begin(), left.end(),
                                      [&](std::size_t cell) { return inView[cell] != 0; }),
                       left.end());
            if (hidden - left.size() < minCells && !area.viewpoints.empty())
                break;
            area.viewpoints.push_back(p);
        }
        areas.push_back(area);
    }
    std::stable_sort(areas.begin(), areas.end(),
                     [](const UnseenArea& a, const UnseenArea& b) { return a.areaM2 > b.areaM2; });
    return areas;
}

}  // namespace toposlam::simulation
