#pragma once
// The pose graph of the graph SLAM: one node per keyframe (the robot's pose, world frame, m
// and rad), one edge per measured relative pose between two keyframes. Optimised with Ceres
// (sparse Cholesky, Levenberg-Marquardt) on one persistent problem that grows with the graph,
// so an optimisation costs the solve and nothing else; loop edges carry a Cauchy loss, so a
// wrong loop that slipped through pulls with bounded force until it is withdrawn (MRPT's
// optimize_graph_spa_levmarq has no robust loss, which is why Ceres). Loops accepted on the
// agreement of many matches are added without it (a few of them, many sigma off, would hardly
// pull through the loss). It saves as MRPT's .graph text format (CNetworkOfPoses2DInf), which
// MRPT's graph-slam app reads. Node 0 is fixed. Edges remember their kind and can be withdrawn
// again (a loop that the optimised graph shows to be wrong).
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>

#include <array>
#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace ceres {
class CostFunction;
class LossFunction;
class Problem;
}  // namespace ceres

namespace toposlam::mapping {

enum class EdgeKind {
    Registration,  ///< scan-to-submap registration (point-to-line ICP)
    GraphMatch,    ///< the graph matcher, where registration failed
    Odometry,      ///< only odometry (registration and graph matcher failed)
    Loop           ///< loop closure (graph matcher, verified)
};
const char* toString(EdgeKind k);

struct PoseGraphEdge {
    std::size_t from = 0, to = 0;
    mrpt::poses::CPose2D measurement;        ///< pose of `to` in the frame of `from`
    mrpt::math::CMatrixDouble33 covariance;  ///< of (x, y, phi), m^2 and rad^2
    EdgeKind kind = EdgeKind::Registration;
    bool active = true;   ///< false once withdrawn
    bool robust = false;  ///< under the Cauchy loss (loops, unless added otherwise)
};

struct OptimizationResult {
    std::size_t iterations = 0;
    double chi2Before = 0, chi2After = 0;  ///< sum over active edges
    double seconds = 0;                    ///< CPU time of this thread
};

class PoseGraph {
  public:
    /// `loopLossScale`: the Cauchy loss scale of loop edges, in standard deviations (their
    /// whitened residual); 0 = plain least squares.
    explicit PoseGraph(double loopLossScale = 3.0);
    ~PoseGraph();
    PoseGraph(const PoseGraph& other);
    PoseGraph& operator=(const PoseGraph& other);

    /// Adds a node at `pose` (its initial estimate); returns its id (0, 1, 2, ...).
    std::size_t addNode(const mrpt::poses::CPose2D& pose);
    std::size_t nodeCount() const { return poses_.size(); }
    mrpt::poses::CPose2D pose(std::size_t node) const {
        const auto& p = poses_[node];
        return {p[0], p[1], p[2]};
    }

    /// Adds an edge; returns its index in edges(). Loop edges get the Cauchy loss unless
    /// `robust` is false (a loop beyond doubt: the agreement of many matches).
    std::size_t addEdge(std::size_t from, std::size_t to, const mrpt::poses::CPose2D& measurement,
                        const mrpt::math::CMatrixDouble33& covariance, EdgeKind kind,
                        bool robust = true);
    /// Withdraws edge `index` (it stays listed, inactive).
    void withdrawEdge(std::size_t index);
    const std::vector<PoseGraphEdge>& edges() const { return edges_; }
    /// Active edges at each node (indices into edges()), for walking the graph.
    const std::vector<std::size_t>& edgesAt(std::size_t node) const { return adjacency_[node]; }

    /// Mahalanobis distance squared of edge `index`'s measurement from the current estimate.
    double chi2(std::size_t index) const;
    /// The same for a measurement that is not (yet) an edge.
    double chi2(std::size_t from, std::size_t to, const mrpt::poses::CPose2D& measurement,
                const mrpt::math::CMatrixDouble33& covariance) const;

    /// Moves the whole graph: every node pose p becomes transform (+) p (edges are relative and
    /// stay as they are).
    void transformNodes(const mrpt::poses::CPose2D& transform);

    /// Optimises the nodes from `firstFree` on (node 0 is always fixed) from the current
    /// estimate; older nodes hold still and anchor the rest. With firstFree > 1 only the
    /// edges that touch a free node enter the problem, so the cost follows the window.
    OptimizationResult optimize(int maxIterations, std::size_t firstFree = 1);
    /// Sum over active edges of their chi-square (no loss function).
    double totalChi2() const;

    /// The graph as MRPT's network (nodes at their current estimate, active edges).
    mrpt::graphs::CNetworkOfPoses2DInf network() const;
    /// Writes MRPT's .graph text format (VERTEX_SE2 / EDGE_SE2 lines) atomically.
    void save(const std::string& path) const;

  private:
    /// Builds the Ceres problem from scratch (after a copy).
    void rebuildProblem();
    void addResidual(std::size_t edge);
    /// Solves `problem`; returns the iterations.
    std::size_t solve(ceres::Problem& problem, int maxIterations);
    /// The problem of the nodes from firstFree on (and the fixed nodes their edges reach).
    std::size_t solveWindow(std::size_t firstFree, int maxIterations);

    double loopLossScale_;
    std::deque<std::array<double, 3>> poses_;  // stable addresses: Ceres parameter blocks
    std::vector<PoseGraphEdge> edges_;
    std::vector<void*> residuals_;  // ceres::ResidualBlockId per edge (nullptr: withdrawn)
    std::vector<ceres::CostFunction*> costs_;   // per edge, owned by problem_
    std::vector<ceres::LossFunction*> losses_;  // per edge (nullptr: none), owned by problem_
    std::vector<std::vector<std::size_t>> adjacency_;
    std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace toposlam::mapping
