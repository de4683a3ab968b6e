#include <toposlam/planning/ShortestGridPath.h>

namespace toposlam::planning {

namespace {

// Step cost 1 on traversable cells, 0 (blocked) elsewhere; row-major like the image.
std::vector<float> unitStepCosts(const TraversabilityGrid& grid) {
    const cv::Mat& traversable = grid.traversable();
    std::vector<float> costs(traversable.total(), 0.0f);
    for (int r = 0; r < traversable.rows; ++r) {
        const auto* row = traversable.ptr<std::uint8_t>(r);
        for (int c = 0; c < traversable.cols; ++c)
            costs[static_cast<std::size_t>(r) * traversable.cols + c] = row[c] ? 1.0f : 0.0f;
    }
    return costs;
}

}  // namespace

ShortestGridPath::ShortestGridPath(const TraversabilityGrid& grid)
    : grid_(grid),
      search_(grid.frame().cols, grid.frame().rows, grid.frame().resolution, unitStepCosts(grid)) {}

std::optional<GridPath> ShortestGridPath::plan(const mrpt::math::TPoint2D& from,
                                               const mrpt::math::TPoint2D& to) {
    const auto& frame = grid_.frame();
    const cv::Point start = frame.toCell(from.x, from.y), goal = frame.toCell(to.x, to.y);
    if (!grid_.isTraversableCell(start) || !grid_.isTraversableCell(goal))
        return std::nullopt;
    const auto cells = search_.path(search_.index(start.x, start.y), search_.index(goal.x, goal.y));
    if (!cells)
        return std::nullopt;
    GridPath path;
    path.length = cells->cost;
    path.points.reserve(cells->cells.size());
    const auto cols = static_cast<std::size_t>(frame.cols);
    for (const std::size_t c : cells->cells)
        path.points.push_back(
            frame.toWorld(static_cast<double>(c % cols), static_cast<double>(c / cols)));
    return path;
}

}  // namespace toposlam::planning
