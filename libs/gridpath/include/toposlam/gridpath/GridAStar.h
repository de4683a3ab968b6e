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

  private:
    struct QueueEntry {
        float priority;
        std::uint32_t cell;
        bool operator<(const QueueEntry& o) const { return priority > o.priority; }  // min-heap
    };
    /// Settles cells from `start` until `goal` is settled (goal < 0: all reachable cells).
    void search(std::uint32_t start, long goal, const Heuristic& heuristic);
    bool visited(std::size_t cell) const { return visitStamp_[cell] == stamp_; }
    float octile(std::uint32_t cell, long goal) const;

    int cols_, rows_;
    float cellSize_;
    std::vector<float> stepCost_;
    // Search state reused by every query; a new stamp marks all cells unvisited without
    // clearing the arrays (no allocation and no O(cells) reset per query).
    std::vector<float> cost_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> visitStamp_;
    std::vector<std::uint8_t> closed_;
    std::vector<QueueEntry> heap_;
    std::vector<float> allCosts_;
    std::uint32_t stamp_ = 0;
};

}  // namespace toposlam::gridpath
