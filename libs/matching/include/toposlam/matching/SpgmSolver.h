#pragma once
// Successive-projection graph matching (SPGM; van Wyk & van Wyk, "A POCS-based graph matching
// algorithm", IEEE TPAMI 26(11), 2004), as the graph-matching paper uses it (eqs. 4-5).
//
// Problem. Over the candidate assignments k = (i -> a) with similarities X, y (Similarity.h),
// find the relaxed assignment matrix P (p = vec P, one entry per candidate; non-candidates
// are 0) that minimises
//     J(p) = -1/2 p'Xp - 1/2 p'p - y'p                                         (eq. 4)
// subject to                                                                   (eq. 5)
//     C_box: 0 <= P_ia <= 1,   C_col: sum_i P_ia <= 1 for every a,
//     C_row: sum_a P_ia = 1 for every row i that has at least one candidate.
// P_ia is then read as the probability that node i matches node a.
//
// Our reconstruction (we had no copy of the 2004 paper; this follows its title and the
// description in the graph-matching paper): projected gradient descent on J, where the
// projection onto C = C_row ∩ C_col ∩ C_box is computed by successive projections onto the
// three convex sets (POCS), each of which has a closed form:
//     row  i: add (1 - sum_a P_ia) / m_i to its m_i candidate entries  (affine set)
//     col  a: if sum_i P_ia > 1, subtract (sum - 1) / m_a from its entries  (half-space)
//     box   : clamp to [0, 1].
// Plain cyclic POCS converges to *a* point of C, not to the projection; we use Dykstra's
// variant of the cycle (it keeps one correction vector per set), which converges to the
// Euclidean projection, so every outer step is an exact projected-gradient step.
//   p_0     = projection of the uniform rows (1 / m_i on each candidate);
//   p_{t+1} = Proj_C(p_t - eta * grad J(p_t)),  grad J = -(X p + p + y),
//   eta     = 1 / (1 + max_k sum_l X_kl)   (1 / Lipschitz bound of grad J, by Gershgorin),
// With this step J never increases (descent lemma + projection inequality), so the iteration
// converges. Convergence test: stop when max_k |p_{t+1,k} - p_{t,k}| < tolerance, or after
// maxIterations. Each Dykstra projection stops when one whole cycle moves no entry by more
// than projectionTolerance, or after projectionCycles cycles.
// When the constraints cannot all hold (more rows than columns can take, e.g. two rows
// whose only candidate is the same column) the cycles end at the cap and P still ranks the
// assignments sensibly; the matcher avoids most such cases by using the smaller graph as
// rows. All work vectors live in the object: solving allocates only when a problem is bigger
// than every previous one.
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/Similarity.h>

#include <cstddef>
#include <vector>

namespace toposlam::matching {

struct SpgmOptions {
    int maxIterations = 30;
    double tolerance = 1e-3;  ///< on max |change| of an entry of P per iteration
    int projectionCycles = 5;
    double projectionTolerance = 1e-6;

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

class SpgmSolver {
  public:
    /// Solves for the candidates of `similarity`; `candidates` must be the vector it was
    /// built from, `rowCount` / `colCount` the node counts of the two graphs. Returns P as
    /// one probability per candidate (valid until the next call).
    const std::vector<double>& solve(const Similarity& similarity,
                                     const std::vector<Assignment>& candidates,
                                     std::size_t rowCount, std::size_t colCount,
                                     const SpgmOptions& options = {});

    const std::vector<double>& probabilities() const { return p_; }
    int iterations() const { return iterations_; }
    bool converged() const { return converged_; }
    /// J(p) of eq. 4 at the returned P.
    double objective() const { return objective_; }

  private:
    void project(const std::vector<Assignment>& candidates, const SpgmOptions& options);

    std::vector<double> p_, q_, g_;
    std::vector<double> incRow_, incCol_, incBox_, before_;
    std::vector<double> sums_;
    std::vector<std::size_t> rowSize_, colSize_;
    int iterations_ = 0;
    bool converged_ = false;
    double objective_ = 0;
};

}  // namespace toposlam::matching
