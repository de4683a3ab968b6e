#include <toposlam/gridpath/GridAStar.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace toposlam::gridpath {

namespace {
constexpr float kSqrt2 = 1.41421356f;
// The eight moves, straight ones first; the order is the order neighbours are queued in, so
// it decides between paths of equal cost and must stay as it is.
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
    for (int k = 0; k < 8; ++k) {
        moveOffset_[k] = static_cast<std::ptrdiff_t>(kDy[k]) * cols_ + kDx[k];
        moveLength_[k] = (k >= 4 ? kSqrt2 : 1.0f) * cellSize_;
    }
    // The moves each cell allows, worked out once: the search's inner loop then needs no
    // bounds or corner tests.
    moves_.assign(cells, 0);
    for (int y = 0; y < rows_; ++y) {
        for (int x = 0; x < cols_; ++x) {
            std::uint8_t allowed = 0;
            for (int k = 0; k < 8; ++k) {
                const int nx = x + kDx[k], ny = y + kDy[k];
                if (!traversable(nx, ny))
                    continue;
                if (k >= 4 && (!traversable(nx, y) || !traversable(x, ny)))
                    continue;  // would cut a blocked cell's corner
                allowed |= static_cast<std::uint8_t>(1u << k);
            }
            moves_[index(x, y)] = allowed;
        }
    }
    state_.resize(cells);
    parent_.resize(cells);
}

float GridAStar::octile(std::uint32_t cell, long goal) const {
    const auto c = static_cast<long>(cell), cols = static_cast<long>(cols_);
    const auto dx = static_cast<float>(std::abs(c % cols - goal % cols));
    const auto dy = static_cast<float>(std::abs(c / cols - goal / cols));
    return cellSize_ * (std::max(dx, dy) + (kSqrt2 - 1.0f) * std::min(dx, dy));
}

void GridAStar::newQuery() {
    // Two stamps per query (reached, settled); a wrap clears the states once every 2^31
    // queries.
    if (stamp_ >= std::numeric_limits<std::uint32_t>::max() - 2) {
        for (CellState& s : state_)
            s.stamp = 0;
        stamp_ = 0;
    }
    stamp_ += 2;
}

// A*'s queue. Its order between entries of equal priority picks among paths of equal cost:
// the simulator's tours and people's walks were made with std's binary heap and stay so.
class GridAStar::AStarQueue {
  public:
    explicit AStarQueue(std::vector<QueueEntry>& heap) : heap_(heap) { heap_.clear(); }
    bool empty() const { return heap_.empty(); }
    void push(float priority, std::uint32_t cell) {
        heap_.push_back({priority, cell});
        std::push_heap(heap_.begin(), heap_.end());
    }
    std::uint32_t pop() {
        std::pop_heap(heap_.begin(), heap_.end());
        const std::uint32_t cell = heap_.back().cell;
        heap_.pop_back();
        return cell;
    }

  private:
    std::vector<QueueEntry>& heap_;
};

template <bool kParents, typename Queue, typename Estimate>
void GridAStar::search(Queue& queue, std::uint32_t start, const Estimate& estimate,
                       std::uint32_t goal, std::size_t targetsLeft) {
    newQuery();
    const std::uint32_t settledStamp = stamp_ + 1;
    state_[start] = {0.0f, stamp_};
    if (kParents)
        parent_[start] = start;
    queue.push(estimate(start), start);
    while (!queue.empty()) {
        const std::uint32_t cell = queue.pop();
        CellState& here = state_[cell];
        if (here.stamp == settledStamp)
            continue;  // a stale entry
        here.stamp = settledStamp;
        if (cell == goal)
            return;
        if (targetsLeft > 0 && isTarget(cell) && --targetsLeft == 0)
            return;
        const float costHere = here.cost;
        for (unsigned allowed = moves_[cell]; allowed != 0; allowed &= allowed - 1) {
            const int k = __builtin_ctz(allowed);
            const auto n =
                static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(cell) + moveOffset_[k]);
            const float c = costHere + moveLength_[k] * stepCost_[n];
            CellState& next = state_[n];
            if (next.stamp == settledStamp || (next.stamp == stamp_ && c >= next.cost))
                continue;
            next = {c, stamp_};
            if (kParents)
                parent_[n] = cell;
            queue.push(c + estimate(n), n);
        }
    }
}

void GridAStar::dijkstra(std::uint32_t start, std::size_t targetsLeft) {
    const auto none = [](std::uint32_t) { return 0.0f; };
    radix_.clear();
    search<false>(radix_, start, none, kNoGoal, targetsLeft);
}

std::optional<CellPath> GridAStar::path(std::size_t start, std::size_t goal,
                                        const Heuristic& heuristic) {
    const auto inGrid = [&](std::size_t c) { return c < stepCost_.size() && stepCost_[c] > 0.0f; };
    if (!inGrid(start) || !inGrid(goal))
        return std::nullopt;
    const auto g = static_cast<std::uint32_t>(goal);
    AStarQueue queue(heap_);
    const auto octileToGoal = [&](std::uint32_t c) { return octile(c, g); };
    if (heuristic)
        search<true>(queue, static_cast<std::uint32_t>(start), heuristic, g, 0);
    else
        search<true>(queue, static_cast<std::uint32_t>(start), octileToGoal, g, 0);
    if (!settled(goal))
        return std::nullopt;
    CellPath result;
    result.cost = state_[goal].cost;
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
    dijkstra(static_cast<std::uint32_t>(start), 0);
    for (std::size_t c = 0; c < allCosts_.size(); ++c) {
        if (settled(c))
            allCosts_[c] = state_[c].cost;
    }
    return allCosts_;
}

std::vector<float> GridAStar::costsTo(std::size_t start, const std::vector<std::size_t>& targets) {
    std::vector<float> costs(targets.size(), kUnreachable);
    if (start >= stepCost_.size() || stepCost_[start] <= 0.0f)
        return costs;
    // Dijkstra until every reachable target is settled: their costs are then final, the same
    // as costsFrom() gives, and the cells farther away are never expanded.
    targetStamp_.resize(stepCost_.size(), 0);
    if (++targetQuery_ == 0) {  // wrapped: clear once every 2^32 queries
        std::fill(targetStamp_.begin(), targetStamp_.end(), 0u);
        targetQuery_ = 1;
    }
    std::size_t distinct = 0;
    for (const std::size_t t : targets) {
        if (t < stepCost_.size() && stepCost_[t] > 0.0f && targetStamp_[t] != targetQuery_) {
            targetStamp_[t] = targetQuery_;
            ++distinct;
        }
    }
    if (distinct == 0)
        return costs;
    dijkstra(static_cast<std::uint32_t>(start), distinct);
    for (std::size_t i = 0; i < targets.size(); ++i) {
        if (targets[i] < stepCost_.size() && settled(targets[i]))
            costs[i] = state_[targets[i]].cost;
    }
    return costs;
}

}  // namespace toposlam::gridpath
