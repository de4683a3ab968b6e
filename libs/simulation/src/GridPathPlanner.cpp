#include <toposlam/simulation/GridPathPlanner.h>

#include <algorithm>
#include <cmath>

namespace toposlam::simulation {

namespace {

// Per cell: the cost per metre of entering it, 1 with clearance above the preferred value,
// up to 1 + clearanceWeight at the minimum; 0 (blocked) below the minimum.
std::vector<float> clearanceStepCosts(const ClearanceMap& map, const PathCostOptions& options) {
    std::vector<float> factor(map.geometry().cellCount(), 0.0f);
    const double pref = std::max(options.preferredClearance, 1e-6);
    for (std::size_t i = 0; i < factor.size(); ++i) {
        const double c = map.clearances()[i];
        if (c < options.minClearance || c <= 0)
            continue;
        const double shortfall = std::clamp((pref - c) / pref, 0.0, 1.0);
        factor[i] = static_cast<float>(1.0 + options.clearanceWeight * shortfall);
    }
    return factor;
}

}  // namespace

GridPathPlanner::GridPathPlanner(const ClearanceMap& map, const PathCostOptions& options)
    : map_(map),
      options_(options),
      search_(map.geometry().sizeX, map.geometry().sizeY, map.geometry().resolution,
              clearanceStepCosts(map, options)) {}

std::vector<mrpt::math::TPoint2D> GridPathPlanner::plan(const mrpt::math::TPoint2D& from,
                                                        const mrpt::math::TPoint2D& to) {
    const GridGeometry& g = map_.geometry();
    if (!traversable(from) || !traversable(to))
        return {};
    // Heuristic: the straight line from a cell's centre to `to` itself, as the simulator has
    // always aimed (its tours and logs stay as they were). It may overestimate the remaining
    // cost by the distance from `to` to its cell's centre (< 0.71 cell), so a path can be that
    // much longer than the cheapest.
    const auto towardsGoal = [&](std::size_t cell) {
        const auto p = g.centre(cell);
        return static_cast<float>(std::hypot(p.x - to.x, p.y - to.y));
    };
    const auto cells = search_.path(g.index(g.cellX(from.x), g.cellY(from.y)),
                                    g.index(g.cellX(to.x), g.cellY(to.y)), towardsGoal);
    if (!cells)
        return {};
    std::vector<mrpt::math::TPoint2D> path;
    path.reserve(cells->cells.size() + 1);
    for (const std::size_t c : cells->cells)
        path.push_back(g.centre(c));
    path.front() = from;
    if (path.size() == 1)
        path.push_back(to);
    path.back() = to;
    return path;
}

std::size_t GridPathPlanner::cellOf(const mrpt::math::TPoint2D& p) const {
    const GridGeometry& g = map_.geometry();
    const int cx = g.cellX(p.x), cy = g.cellY(p.y);
    return g.contains(cx, cy) ? g.index(cx, cy) : g.cellCount();
}

const std::vector<float>& GridPathPlanner::costsFrom(const mrpt::math::TPoint2D& from) {
    return search_.costsFrom(cellOf(from));
}

std::vector<float> GridPathPlanner::costsTo(const mrpt::math::TPoint2D& from,
                                            const std::vector<mrpt::math::TPoint2D>& to) {
    std::vector<std::size_t> targets;
    targets.reserve(to.size());
    for (const auto& p : to)
        targets.push_back(cellOf(p));
    return search_.costsTo(cellOf(from), targets);
}

}  // namespace toposlam::simulation
