#pragma once
// The similarities of two attributed graphs (graph-matching paper, eqs. 2 and 3), over a set
// of candidate assignments k = (i -> a), node i of the "row" graph G to node a of the
// "column" graph G':
//   y_k  = alpha / (|A_i - A'_a| + alpha)                               node similarity
//   X_kl = alpha / (sum_g |B_g(i, j) - B'_g(a, b)| + alpha)             edge similarity,
// for l = (j -> b). The paper uses alpha = 1 and sums the four edge attributes as they are
// (rad, ratio, m, m). Angle differences are wrapped into [0, pi].
// X is sparse: it is stored only for pairs of assignments that can both hold, i.e. i != j,
// a != b (a one-to-one matching never holds both otherwise; X_kk = 0, the node term is y),
// and whose edge angles differ by at most maxAngleDifference: two edges that disagree by
// more cannot be the same pair of walls, and dropping them turns the (n n')^2 matrix into a
// few entries per assignment.
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/AttributedGraph.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace toposlam::matching {

/// Candidate assignment k: node `row` of the row graph to node `col` of the column graph.
struct Assignment {
    std::uint32_t row = 0;
    std::uint32_t col = 0;
};

struct SimilarityOptions {
    double alpha = 1.0;                ///< control parameter of eqs. 2-3 (paper: 1)
    double maxAngleDifference = 0.35;  ///< rad; edge pairs beyond it get X = 0

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

class Similarity {
  public:
    /// Computes y and the sparse X for `candidates`; entry k of y (row k of X) belongs to
    /// candidates[k].
    void build(const AttributedGraph& rows, const AttributedGraph& cols,
               const std::vector<Assignment>& candidates, const SimilarityOptions& options);

    std::size_t size() const { return y_.size(); }
    const std::vector<double>& y() const { return y_; }
    /// out = X p (out is resized).
    void multiply(const std::vector<double>& p, std::vector<double>& out) const;
    /// X_kl (a search in row k; for tests and diagnostics).
    double x(std::size_t k, std::size_t l) const;
    /// Largest row sum of X: with it, 1 + maxRowSum() bounds the largest eigenvalue of X + I.
    double maxRowSum() const { return maxRowSum_; }
    std::size_t nonZeros() const { return values_.size(); }

  private:
    std::vector<double> y_;
    std::vector<std::uint32_t> rowStart_, columns_;  // CSR
    std::vector<double> values_;
    std::vector<std::uint32_t> byRowStart_, byRow_, cursor_;  // candidates grouped by row node
    double maxRowSum_ = 0;
};

}  // namespace toposlam::matching
