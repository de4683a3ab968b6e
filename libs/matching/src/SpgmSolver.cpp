#include <toposlam/matching/SpgmSolver.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

void SpgmOptions::declare(config::OptionsSchema& s) {
    s.integer("max_iterations", maxIterations, "", "SPGM iterations at most").within(1, 10000);
    s.real("tolerance", tolerance, "", "stop when no entry of P changes by more").above(0);
    s.integer("projection_cycles", projectionCycles, "",
              "Dykstra cycles per projection onto the constraints of eq. 5")
        .within(1, 1000);
    s.real("projection_tolerance", projectionTolerance, "", "Dykstra's stopping tolerance")
        .above(0);
}

const std::vector<double>& SpgmSolver::solve(const Similarity& similarity,
                                             const std::vector<Assignment>& candidates,
                                             std::size_t rowCount, std::size_t colCount,
                                             const SpgmOptions& options) {
    const std::size_t K = candidates.size();
    iterations_ = 0;
    converged_ = false;
    objective_ = 0;
    p_.resize(K);
    if (K == 0) {
        converged_ = true;
        return p_;
    }
    rowSize_.assign(rowCount, 0);
    colSize_.assign(colCount, 0);
    for (const Assignment& c : candidates) {
        ++rowSize_[c.row];
        ++colSize_[c.col];
    }

    // Start: every row spreads its unit mass evenly over its candidates, then made feasible.
    q_.resize(K);
    for (std::size_t k = 0; k < K; ++k)
        q_[k] = 1.0 / double(rowSize_[candidates[k].row]);
    project(candidates, options);

    const std::vector<double>& y = similarity.y();
    const double eta = 1.0 / (1.0 + similarity.maxRowSum());
    for (int t = 0; t < options.maxIterations; ++t) {
        similarity.multiply(p_, g_);
        for (std::size_t k = 0; k < K; ++k)
            q_[k] = p_[k] + eta * (g_[k] + p_[k] + y[k]);
        before_ = p_;
        project(candidates, options);
        iterations_ = t + 1;
        double change = 0;
        for (std::size_t k = 0; k < K; ++k)
            change = std::max(change, std::abs(p_[k] - before_[k]));
        if (change < options.tolerance) {
            converged_ = true;
            break;
        }
    }

    similarity.multiply(p_, g_);
    for (std::size_t k = 0; k < K; ++k)
        objective_ -= 0.5 * p_[k] * (g_[k] + p_[k]) + y[k] * p_[k];
    return p_;
}

void SpgmSolver::project(const std::vector<Assignment>& candidates, const SpgmOptions& options) {
    // Dykstra's cyclic projection of q_ onto C_row ∩ C_col ∩ C_box; result in p_.
    const std::size_t K = candidates.size();
    p_ = q_;
    incRow_.assign(K, 0.0);
    incCol_.assign(K, 0.0);
    incBox_.assign(K, 0.0);
    for (int cycle = 0; cycle < options.projectionCycles; ++cycle) {
        double change = 0;

        // Rows: sum_a P_ia = 1.
        for (std::size_t k = 0; k < K; ++k)
            q_[k] = p_[k] + incRow_[k];
        sums_.assign(rowSize_.size(), 0.0);
        for (std::size_t k = 0; k < K; ++k)
            sums_[candidates[k].row] += q_[k];
        for (std::size_t k = 0; k < K; ++k) {
            const std::size_t i = candidates[k].row;
            const double v = q_[k] + (1.0 - sums_[i]) / double(rowSize_[i]);
            incRow_[k] = q_[k] - v;
            change = std::max(change, std::abs(v - p_[k]));
            p_[k] = v;
        }

        // Columns: sum_i P_ia <= 1.
        for (std::size_t k = 0; k < K; ++k)
            q_[k] = p_[k] + incCol_[k];
        sums_.assign(colSize_.size(), 0.0);
        for (std::size_t k = 0; k < K; ++k)
            sums_[candidates[k].col] += q_[k];
        for (std::size_t k = 0; k < K; ++k) {
            const std::size_t a = candidates[k].col;
            const double excess = sums_[a] - 1.0;
            const double v = excess > 0 ? q_[k] - excess / double(colSize_[a]) : q_[k];
            incCol_[k] = q_[k] - v;
            change = std::max(change, std::abs(v - p_[k]));
            p_[k] = v;
        }

        // Box: 0 <= P_ia <= 1.
        for (std::size_t k = 0; k < K; ++k) {
            const double w = p_[k] + incBox_[k];
            const double v = std::clamp(w, 0.0, 1.0);
            incBox_[k] = w - v;
            change = std::max(change, std::abs(v - p_[k]));
            p_[k] = v;
        }
        if (change < options.projectionTolerance)
            break;
    }
}

}  // namespace toposlam::matching
