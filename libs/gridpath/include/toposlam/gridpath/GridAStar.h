#pragma once
// The one grid shortest-path search of TopoSLAM (the simulator's clearance-keeping paths, the
// planner's reference paths): A* between two cells and Dijkstra from one cell to all, over the
// 8-connected cells of a raster. Frame-free: cells are indices i = y * cols + x of a row-major
// raster, whatever world frame the caller's raster has.
//
// A move into cell n costs its length (1 or sqrt(2) cells, times cellSize) times stepCost[n];
// stepCost 0 marks a blocked cell. Diagonal moves may not cut the corner of a blocked cell.
// The default A* heuristic is the octile distance times cellSize: exact on an empty grid with
// all costs 1, and admissible because every step cost is at least 1.
//
// Speed: each cell's allowed moves are a table made once, so the inner loop tests no bounds or
// corners. Dijkstra queues cells in a RadixHeap: its costs do not depend on the order of cells
// of equal cost. A* keeps std's binary heap, whose order picks among equal-cost paths (the
// simulator's tours and logs were made with it).
#include <toposlam/gridpath/RadixHeap.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace toposlam::gridpath {

struct CellPath {
    std::vector<std::size_t> cells;  ///< from start to goal, both included
    double cost = 0;                 ///< in cellSize units (m when cellSize is in m)
};

class GridAStar {
  public:
    static constexpr float kUnreachable = std::numeric_limits<float>::infinity();

    /// `stepCost`: cols * rows values, row-major; >= 1 where a cell can be entered (the cost per
    /// unit of length inside it), 0 where it is blocked. Throws std::invalid_argument when the
    /// sizes disagree or a cost is negative, in (0, 1) or not finite.
    GridAStar(int cols, int rows, double cellSize, std::vector<float> stepCost);

    int cols() const { return cols_; }
    int rows() const { return rows_; }
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(cols_) +
               static_cast<std::size_t>(x);
    }
    bool traversable(int x, int y) const {
        return x >= 0 && y >= 0 && x < cols_ && y < rows_ && stepCost_[index(x, y)] > 0.0f;
    }

    /// An estimate of the cost from a cell to the goal (cellSize units). With one that never
    /// overestimates, path() is the cheapest.
    using Heuristic = std::function<float(std::size_t cell)>;

    /// The cheapest path from cell `start` to cell `goal`; nullopt when either is blocked or
    /// they are not connected. `heuristic`: the octile distance when empty.
    std::optional<CellPath> path(std::size_t start, std::size_t goal,
                                 const Heuristic& heuristic = {});

    /// Path cost from cell `start` to every cell (kUnreachable where there is none; all
    /// kUnreachable when `start` is blocked). The reference stays valid until the next call.
    const std::vector<float>& costsFrom(std::size_t start);

    /// Path cost from cell `start` to each cell of `targets`, in their order: the values
    /// costsFrom() gives for them, from a search that stops once every target is settled
    /// (kUnreachable for a target that is blocked, outside the grid or not connected).
    std::vector<float> costsTo(std::size_t start, const std::vector<std::size_t>& targets);

  private:
    struct QueueEntry {
        float priority;
        std::uint32_t cell;
        bool operator<(const QueueEntry& o) const { return priority > o.priority; }  // min-heap
    };
    /// A cell's search state. `stamp` is the query's stamp once the cell is reached, that
    /// plus one once it is settled; older stamps mean untouched by this query.
    struct CellState {
        float cost;  ///< cellSize units from the start
        std::uint32_t stamp;
    };
    static constexpr std::uint32_t kNoGoal = std::numeric_limits<std::uint32_t>::max();

    class AStarQueue;  ///< std's binary heap over heap_ (GridAStar.cpp)

    /// Settles cells from `start`, queued in `queue` by cost + estimate(cell), until `goal` is
    /// settled or, with `targetsLeft` > 0, until that many cells marked as targets are; else
    /// all reachable ones. With kParents, parent_ records each cell's predecessor.
    template <bool kParents, typename Queue, typename Estimate>
    void search(Queue& queue, std::uint32_t start, const Estimate& estimate, std::uint32_t goal,
                std::size_t targetsLeft);
    /// Dijkstra from `start` (costs only: any queue order gives the same ones).
    void dijkstra(std::uint32_t start, std::size_t targetsLeft);
    void newQuery();
    bool settled(std::size_t cell) const { return state_[cell].stamp == stamp_ + 1; }
    bool isTarget(std::size_t cell) const { return targetStamp_[cell] == targetQuery_; }
    float octile(std::uint32_t cell, long goal) const;

    int cols_, rows_;
    float cellSize_;
    std::vector<float> stepCost_;
    std::vector<std::uint8_t> moves_;  ///< per cell: bit k set where move k is allowed
    std::ptrdiff_t moveOffset_[8];     ///< index step of each move
    float moveLength_[8];              ///< its length, cellSize units
    // Search state reused by every query; a new stamp marks all cells untouched without
    // clearing the arrays (no allocation and no O(cells) reset per query).
    std::vector<CellState> state_;
    std::vector<std::uint32_t> parent_;  ///< A*'s: the cell each was reached from
    std::vector<QueueEntry> heap_;       ///< A*'s queue
    RadixHeap radix_;                    ///< Dijkstra's queue, several times faster
    std::vector<float> allCosts_;
    std::vector<std::uint32_t> targetStamp_;  ///< costsTo's targets: == targetQuery_
    std::uint32_t stamp_ = 0;
    std::uint32_t targetQuery_ = 0;
};

}  // namespace toposlam::gridpath
