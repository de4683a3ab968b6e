#include <toposlam/matching/GreedyAssignment.h>

#include <algorithm>
#include <numeric>

namespace toposlam::matching {

const std::vector<AssignedPair>& GreedyAssignment::solve(const std::vector<Assignment>& candidates,
                                                         const std::vector<double>& probabilities,
                                                         std::size_t rowCount, std::size_t colCount,
                                                         double minProbability) {
    pairs_.clear();
    order_.resize(candidates.size());
    std::iota(order_.begin(), order_.end(), 0u);
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t u, std::uint32_t v) {
        if (probabilities[u] != probabilities[v])
            return probabilities[u] > probabilities[v];
        if (candidates[u].row != candidates[v].row)
            return candidates[u].row < candidates[v].row;
        return candidates[u].col < candidates[v].col;
    });
    rowUsed_.assign(rowCount, 0);
    colUsed_.assign(colCount, 0);
    for (std::uint32_t k : order_) {
        if (probabilities[k] < minProbability)
            break;
        const Assignment& c = candidates[k];
        if (rowUsed_[c.row] || colUsed_[c.col])
            continue;
        rowUsed_[c.row] = colUsed_[c.col] = 1;
        pairs_.push_back({c.row, c.col, probabilities[k], k});
    }
    return pairs_;
}

}  // namespace toposlam::matching
