#include <toposlam/planning/GridAStar.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace toposlam::planning {

namespace {
constexpr float kSqrt2 = 1.41421356f;
// Octile distance: exact shortest 8-connected distance without obstacles (admissible).
float octile(int dx, int dy) {
    dx = std::abs(dx);
    dy = std::abs(dy);
    return static_cast<float>(std::max(dx, dy) - std::min(dx, dy)) +
           kSqrt2 * static_cast<float>(std::min(dx, dy));
}
}  // namespace

GridAStar::GridAStar(const TraversabilityGrid& grid) : grid_(grid) {
    const auto cells =
        static_cast<std::size_t>(grid.frame().cols) * static_cast<std::size_t>(grid.frame().rows);
    cost_.resize(cells);
    parent_.resize(cells);
    visitedStamp_.assign(cells, 0);
}

std::optional<GridPath> GridAStar::plan(const mrpt::math::TPoint2D& from,
                                        const mrpt::math::TPoint2D& to) {
    const auto& frame = grid_.frame();
    const cv::Point start = frame.toCell(from.x, from.y), goal = frame.toCell(to.x, to.y);
    if (!grid_.isTraversableCell(start) || !grid_.isTraversableCell(goal))
        return std::nullopt;
    const int cols = frame.cols;
    const auto index = [cols](const cv::Point& p) { return p.y * cols + p.x; };

    // A new stamp marks every cell unvisited without clearing the arrays.
    if (++stamp_ == 0) {
        std::fill(visitedStamp_.begin(), visitedStamp_.end(), 0u);
        stamp_ = 1;
    }
    using Entry = std::pair<float, int>;  // (cost + heuristic, cell)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    const int s = index(start), g = index(goal);
    cost_[s] = 0;
    parent_[s] = -1;
    visitedStamp_[s] = stamp_;
    open.emplace(octile(goal.x - start.x, goal.y - start.y), s);

    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
    static const int dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    while (!open.empty()) {
        const auto [f, cell] = open.top();
        open.pop();
        const cv::Point p(cell % cols, cell / cols);
        if (f > cost_[cell] + octile(goal.x - p.x, goal.y - p.y) + 1e-4f)
            continue;  // stale
        if (cell == g)
            break;
        for (int k = 0; k < 8; ++k) {
            const cv::Point q(p.x + dx[k], p.y + dy[k]);
            if (!grid_.isTraversableCell(q))
                continue;
            // A diagonal step must not cut the corner of a blocked cell.
            if (k >= 4 && (!grid_.isTraversableCell({p.x + dx[k], p.y}) ||
                           !grid_.isTraversableCell({p.x, p.y + dy[k]}))) {
                continue;
            }
            const int qi = index(q);
            const float c = cost_[cell] + (k >= 4 ? kSqrt2 : 1.0f);
            if (visitedStamp_[qi] == stamp_ && c >= cost_[qi])
                continue;
            visitedStamp_[qi] = stamp_;
            cost_[qi] = c;
            parent_[qi] = cell;
            open.emplace(c + octile(goal.x - q.x, goal.y - q.y), qi);
        }
    }
    if (visitedStamp_[g] != stamp_)
        return std::nullopt;

    GridPath path;
    for (int c = g; c != -1; c = parent_[c])
        path.points.push_back(frame.toWorld(c % cols, c / cols));
    std::reverse(path.points.begin(), path.points.end());
    path.length = static_cast<double>(cost_[g]) * frame.resolution;
    return path;
}

}  // namespace toposlam::planning
