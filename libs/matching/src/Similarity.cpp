#include <toposlam/matching/Similarity.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

void SimilarityOptions::declare(config::OptionsSchema& s) {
    s.real("alpha", alpha, "", "control parameter of eqs. 2-3 (paper: 1)").above(0);
    s.angle("max_angle_difference", maxAngleDifference,
            "edge pairs with more angle difference get X = 0")
        .above(0)
        .atMost(180);
}

void Similarity::build(const AttributedGraph& rows, const AttributedGraph& cols,
                       const std::vector<Assignment>& candidates,
                       const SimilarityOptions& options) {
    const std::size_t K = candidates.size();
    const double alpha = options.alpha;
    y_.resize(K);
    for (std::size_t k = 0; k < K; ++k) {
        const double dA = rows.node(candidates[k].row).length - cols.node(candidates[k].col).length;
        y_[k] = alpha / (std::abs(dA) + alpha);
    }

    // Group candidates by row node so that the pairs (k, l) are visited as (i, j) blocks.
    const std::size_t n = rows.size();
    byRowStart_.assign(n + 1, 0);
    for (const Assignment& c : candidates)
        ++byRowStart_[c.row + 1];
    for (std::size_t i = 0; i < n; ++i)
        byRowStart_[i + 1] += byRowStart_[i];
    byRow_.resize(K);
    cursor_.assign(byRowStart_.begin(), byRowStart_.end() - 1);
    for (std::size_t k = 0; k < K; ++k)
        byRow_[cursor_[candidates[k].row]++] = std::uint32_t(k);

    rowStart_.resize(K + 1);
    columns_.clear();
    values_.clear();
    maxRowSum_ = 0;
    // Row k of X, k = (i -> a): every l = (j -> b) with j != i, b != a and compatible angles.
    // Rows are produced in candidate order so that CSR row k is row k.
    for (std::size_t k = 0; k < K; ++k) {
        rowStart_[k] = static_cast<std::uint32_t>(values_.size());
        const std::uint32_t i = candidates[k].row, a = candidates[k].col;
        double rowSum = 0;
        for (std::uint32_t j = 0; j < n; ++j) {
            if (j == i)
                continue;
            const AttributedGraph::EdgeAttributes& B = rows.edge(i, j);
            for (std::uint32_t m = byRowStart_[j]; m < byRowStart_[j + 1]; ++m) {
                const std::uint32_t l = byRow_[m];
                const std::uint32_t b = candidates[l].col;
                if (b == a)
                    continue;
                const AttributedGraph::EdgeAttributes& Bp = cols.edge(a, b);
                // Both angles are in (-pi, pi]: one turn at most brings the difference back.
                double dAngle = std::abs(B[0] - Bp[0]);
                if (dAngle > M_PI)
                    dAngle = 2 * M_PI - dAngle;
                if (dAngle > options.maxAngleDifference)
                    continue;
                const double sum = dAngle + std::abs(B[1] - Bp[1]) + std::abs(B[2] - Bp[2]) +
                                   std::abs(B[3] - Bp[3]);
                const double x = alpha / (sum + alpha);
                columns_.push_back(l);
                values_.push_back(x);
                rowSum += x;
            }
        }
        maxRowSum_ = std::max(maxRowSum_, rowSum);
    }
    rowStart_[K] = static_cast<std::uint32_t>(values_.size());
}

void Similarity::multiply(const std::vector<double>& p, std::vector<double>& out) const {
    const std::size_t K = y_.size();
    out.resize(K);
    for (std::size_t k = 0; k < K; ++k) {
        double s = 0;
        for (std::uint32_t e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
            s += values_[e] * p[columns_[e]];
        out[k] = s;
    }
}

double Similarity::x(std::size_t k, std::size_t l) const {
    for (std::uint32_t e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
        if (columns_[e] == l)
            return values_[e];
    return 0.0;
}

}  // namespace toposlam::matching
