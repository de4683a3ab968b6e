#include <toposlam/gridpath/GridAStar.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace toposlam::gridpath {

namespace {
constexpr float kSqrt2 = 1.41421356f;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
}  // namespace

GridAStar::GridAStar(int cols, int rows, double cellSize, std::vector<float> stepCost)
    : cols_(cols),
      rows_(rows),
      cellSize_(static_cast<float>(cellSize)),
      stepCost_(std::move(stepCost)) {
    const auto cells =
        static_cast<std::size_t>(std::max(cols, 0)) * static_cast<std::size_t>(std::max(rows, 0));
    if (cols < 0 || rows < 0 || stepCost_.size() != cells)
        throw std::invalid_argument("GridAStar: expected cols x rows step costs");
    if (!(cellSize > 0) || !std::isfinite(cellSize))
        throw std::invalid_argument("GridAStar: the cell size must be > 0");
    for (const float c : stepCost_) {
        if (!(c == 0.0f || (c >= 1.0f && std::isfinite(c))))
            throw std::invalid_argument("GridAStar: step costs must be 0 (blocked) or >= 1");
    }
    cost_.resize(cells);
    parent_.resize(cells);
    visitStamp_.assign(cells, 0);
    closed_.assign(cells, 0);
}

float GridAStar::octile(std::uint32_t cell, long goal) const {
    const auto c = static_cast<long>(cell), cols = static_cast<long>(cols_);
    const auto dx = static_cast<float>(std::abs(c % cols - goal % cols));
    const auto dy = static_cast<float>(std::abs(c / cols - goal / cols));
    return cellSize_ * (std::max(dx, dy) + (kSqrt2 - 1.0f) * std::min(dx, dy));
}

void GridAStar::search(std::uint32_t start, long goal, const Heuristic& heuristic) {
    // Dijkstra without a goal; A* with the caller's or the octile estimate.
    const auto estimate = [&](std::uint32_t cell) {
        return goal < 0 ? 0.0f : heuristic ? heuristic(cell) : octile(cell, goal);
    };
    if (++stamp_ == 0) {  // wrapped: clear once every 2^32 queries
        std::fill(visitStamp_.begin(), visitStamp_.end(), 0u);
        stamp_ = 1;
    }
    heap_.clear();
    visitStamp_[start] = stamp_;
    closed_[start] = 0;
    cost_[start] = 0.0f;
    parent_[start] = start;
    heap_.push_back({estimate(start), start});
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end());
        const std::uint32_t cell = heap_.back().cell;
        heap_.pop_back();
        if (closed_[cell])
            continue;  // a stale entry
        closed_[cell] = 1;
        if (goal >= 0 && cell == static_cast<std::uint32_t>(goal))
            return;
        const int x = static_cast<int>(cell % static_cast<std::uint32_t>(cols_));
        const int y = static_cast<int>(cell / static_cast<std::uint32_t>(cols_));
        for (int k = 0; k < 8; ++k) {
            const int nx = x + kDx[k], ny = y + kDy[k];
            if (!traversable(nx, ny))
                continue;
            if (k >= 4 && (!traversable(nx, y) || !traversable(x, ny)))
                continue;  // would cut a blocked cell's corner
            const auto n = static_cast<std::uint32_t>(index(nx, ny));
            const float c = cost_[cell] + (k >= 4 ? kSqrt2 : 1.0f) * cellSize_ * stepCost_[n];
            if (visited(n) && (closed_[n] || c >= cost_[n]))
                continue;
            visitStamp_[n] = stamp_;
            closed_[n] = 0;
            cost_[n] = c;
            parent_[n] = cell;
            heap_.push_back({c + estimate(n), n});
            std::push_heap(heap_.begin(), heap_.end());
        }
    }
}

std::optional<CellPath> GridAStar::path(std::size_t start, std::size_t goal,
                                        const Heuristic& heuristic) {
    const auto inGrid = [&](std::size_t c) { return c < stepCost_.size() && stepCost_[c] > 0.0f; };
    if (!inGrid(start) || !inGrid(goal))
        return std::nullopt;
    search(static_cast<std::uint32_t>(start), static_cast<long>(goal), heuristic);
    if (!visited(goal) || !closed_[goal])
        return std::nullopt;
    CellPath result;
    result.cost = cost_[goal];
    for (std::size_t c = goal;; c = parent_[c]) {
        result.cells.push_back(c);
        if (c == start)
            break;
    }
    std::reverse(result.cells.begin(), result.cells.end());
    return result;
}

const std::vector<float>& GridAStar::costsFrom(std::size_t start) {
    allCosts_.assign(stepCost_.size(), kUnreachable);
    if (start >= stepCost_.size() || stepCost_[start] <= 0.0f)
        return allCosts_;
    search(static_cast<std::uint32_t>(start), -1, {});
    for (std::size_t c = 0; c < allCosts_.size(); ++c) {
        if (visited(c))
            allCosts_[c] = cost_[c];
    }
    return allCosts_;
}

}  // namespace toposlam::gridpath
