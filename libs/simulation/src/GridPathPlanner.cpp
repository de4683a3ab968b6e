#include <toposlam/simulation/GridPathPlanner.h>

#include <algorithm>
#include <cmath>

namespace toposlam::simulation {

GridPathPlanner::GridPathPlanner(const ClearanceMap& map, const PathCostOptions& options)
    : map_(map),
      options_(options),
      stepFactor_(map.geometry().cellCount(), 0.0f),
      cost_(map.geometry().cellCount(), kUnreachable),
      parent_(map.geometry().cellCount(), 0),
      closed_(map.geometry().cellCount(), 0) {
    const double pref = std::max(options.preferredClearance, 1e-6);
    for (std::size_t i = 0; i < stepFactor_.size(); ++i) {
        const double c = map.clearances()[i];
        if (c < options.minClearance || c <= 0)
            continue;
        const double shortfall = std::clamp((pref - c) / pref, 0.0, 1.0);
        stepFactor_[i] = static_cast<float>(1.0 + options.clearanceWeight * shortfall);
    }
}

bool GridPathPlanner::search(std::uint32_t start, long goal) {
    const GridGeometry& g = map_.geometry();
    std::fill(cost_.begin(), cost_.end(), kUnreachable);
    std::fill(closed_.begin(), closed_.end(), 0);
    heap_.clear();
    const float res = static_cast<float>(g.resolution);
    // A* heuristic: straight-line distance (admissible: every step factor is >= 1).
    const auto heuristic = [&](std::uint32_t cell) -> float {
        if (goal < 0)
            return 0.0f;
        const auto p = g.centre(static_cast<std::size_t>(cell));
        return static_cast<float>(std::hypot(p.x - goalX_, p.y - goalY_));
    };
    cost_[start] = 0.0f;
    parent_[start] = start;
    heap_.push_back({heuristic(start), start});
    static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
    static constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end());
        const QueueEntry top = heap_.back();
        heap_.pop_back();
        if (closed_[top.cell])
            continue;
        closed_[top.cell] = 1;
        if (goal >= 0 && top.cell == static_cast<std::uint32_t>(goal))
            return true;
        const int cx = static_cast<int>(top.cell % static_cast<std::uint32_t>(g.sizeX));
        const int cy = static_cast<int>(top.cell / static_cast<std::uint32_t>(g.sizeX));
        for (int k = 0; k < 8; ++k) {
            const int nx = cx + kDx[k], ny = cy + kDy[k];
            if (!traversable(nx, ny))
                continue;
            // Diagonal moves must not squeeze between two blocked cells' corners.
            if (k >= 4 && (!traversable(cx + kDx[k], cy) || !traversable(cx, cy + kDy[k]))) {
                continue;
            }
            const auto n = static_cast<std::uint32_t>(g.index(nx, ny));
            if (closed_[n])
                continue;
            const float len = k >= 4 ? res * static_cast<float>(M_SQRT2) : res;
            const float c = cost_[top.cell] + len * stepFactor_[n];
            if (c < cost_[n]) {
                cost_[n] = c;
                parent_[n] = top.cell;
                heap_.push_back({c + heuristic(n), n});
                std::push_heap(heap_.begin(), heap_.end());
            }
        }
    }
    return goal < 0;
}

std::vector<mrpt::math::TPoint2D> GridPathPlanner::plan(const mrpt::math::TPoint2D& from,
                                                        const mrpt::math::TPoint2D& to) {
    const GridGeometry& g = map_.geometry();
    if (!traversable(from) || !traversable(to))
        return {};
    const auto start = static_cast<std::uint32_t>(g.index(g.cellX(from.x), g.cellY(from.y)));
    const auto goal = static_cast<std::uint32_t>(g.index(g.cellX(to.x), g.cellY(to.y)));
    goalX_ = to.x;
    goalY_ = to.y;
    if (!search(start, goal))
        return {};
    std::vector<mrpt::math::TPoint2D> path;
    for (std::uint32_t c = goal;; c = parent_[c]) {
        path.push_back(g.centre(static_cast<std::size_t>(c)));
        if (c == start)
            break;
    }
    std::reverse(path.begin(), path.end());
    path.front() = from;
    if (path.size() == 1)
        path.push_back(to);
    path.back() = to;
    return path;
}

const std::vector<float>& GridPathPlanner::costsFrom(const mrpt::math::TPoint2D& from) {
    const GridGeometry& g = map_.geometry();
    if (!traversable(from)) {
        std::fill(cost_.begin(), cost_.end(), kUnreachable);
        return cost_;
    }
    search(static_cast<std::uint32_t>(g.index(g.cellX(from.x), g.cellY(from.y))), -1);
    return cost_;
}

}  // namespace toposlam::simulation
