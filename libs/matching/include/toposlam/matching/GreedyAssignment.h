#pragma once
// Discretisation of SPGM's relaxed assignment matrix (graph-matching paper, end of sec. 2.2:
// "select in turn the pair with the largest probability"): repeatedly take the candidate
// (i -> a) with the largest P_ia whose row i and column a are both still free, until no
// candidate of at least minProbability is left. The result is one-to-one.
// Ties are broken by (row, col) so the outcome does not depend on the candidates' order.
#include <toposlam/matching/Similarity.h>

#include <cstddef>
#include <vector>

namespace toposlam::matching {

struct AssignedPair {
    std::uint32_t row = 0, col = 0;
    double probability = 0;
    std::uint32_t candidate = 0;  ///< index k in the candidate list
};

class GreedyAssignment {
  public:
    /// Returns the chosen pairs in the order they were taken (decreasing probability).
    const std::vector<AssignedPair>& solve(const std::vector<Assignment>& candidates,
                                           const std::vector<double>& probabilities,
                                           std::size_t rowCount, std::size_t colCount,
                                           double minProbability = 1e-3);
    const std::vector<AssignedPair>& pairs() const { return pairs_; }

  private:
    std::vector<std::uint32_t> order_;
    std::vector<char> rowUsed_, colUsed_;
    std::vector<AssignedPair> pairs_;
};

}  // namespace toposlam::matching
