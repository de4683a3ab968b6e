#include <ceres/ceres.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/mapping/PoseGraph.h>
#include <toposlam/mapping/RelativePoseError.h>

#include <Eigen/Dense>
#include <algorithm>

namespace toposlam::mapping {

using mrpt::poses::CPose2D;

const char* toString(EdgeKind k) {
    switch (k) {
        case EdgeKind::Registration:
            return "registration";
        case EdgeKind::GraphMatch:
            return "graph matcher";
        case EdgeKind::Odometry:
            return "odometry";
        case EdgeKind::Loop:
            return "loop";
    }
    return "?";
}

namespace {
ceres::Problem::Options problemOptions() {
    ceres::Problem::Options o;
    // The problem owns the cost and loss functions; the parameter blocks are the graph's.
    o.enable_fast_removal = true;  // withdrawing a loop is O(1)
    return o;
}
}  // namespace

PoseGraph::PoseGraph(double loopLossScale)
    : loopLossScale_(loopLossScale), problem_(std::make_unique<ceres::Problem>(problemOptions())) {}

PoseGraph::~PoseGraph() = default;

PoseGraph::PoseGraph(const PoseGraph& other)
    : loopLossScale_(other.loopLossScale_),
      poses_(other.poses_),
      edges_(other.edges_),
      adjacency_(other.adjacency_) {
    rebuildProblem();
}

PoseGraph& PoseGraph::operator=(const PoseGraph& other) {
    if (this != &other) {
        loopLossScale_ = other.loopLossScale_;
        poses_ = other.poses_;
        edges_ = other.edges_;
        adjacency_ = other.adjacency_;
        rebuildProblem();
    }
    return *this;
}

void PoseGraph::rebuildProblem() {
    problem_ = std::make_unique<ceres::Problem>(problemOptions());
    residuals_.assign(edges_.size(), nullptr);
    costs_.assign(edges_.size(), nullptr);
    losses_.assign(edges_.size(), nullptr);
    for (std::size_t i = 0; i < poses_.size(); ++i) {
        problem_->AddParameterBlock(poses_[i].data(), 3);
        if (i == 0)
            problem_->SetParameterBlockConstant(poses_[i].data());
    }
    for (std::size_t e = 0; e < edges_.size(); ++e)
        if (edges_[e].active)
            addResidual(e);
}

std::size_t PoseGraph::addNode(const CPose2D& pose) {
    poses_.push_back({pose.x(), pose.y(), pose.phi()});
    adjacency_.emplace_back();
    problem_->AddParameterBlock(poses_.back().data(), 3);
    if (poses_.size() == 1)
        problem_->SetParameterBlockConstant(poses_.back().data());
    return poses_.size() - 1;
}

void PoseGraph::addResidual(std::size_t index) {
    const PoseGraphEdge& e = edges_[index];
    const Eigen::Matrix3d information = e.covariance.asEigen().inverse();
    const Eigen::Matrix3d sqrtInformation = information.llt().matrixU();
    costs_[index] = makeRelativePoseError(e.measurement, sqrtInformation);
    losses_[index] =
        e.robust && loopLossScale_ > 0 ? new ceres::CauchyLoss(loopLossScale_) : nullptr;
    residuals_[index] = problem_->AddResidualBlock(costs_[index], losses_[index],
                                                   poses_[e.from].data(), poses_[e.to].data());
}

std::size_t PoseGraph::addEdge(std::size_t from, std::size_t to, const CPose2D& measurement,
                               const mrpt::math::CMatrixDouble33& covariance, EdgeKind kind,
                               bool robust) {
    edges_.push_back(
        {from, to, measurement, covariance, kind, true, robust && kind == EdgeKind::Loop});
    residuals_.push_back(nullptr);
    costs_.push_back(nullptr);
    losses_.push_back(nullptr);
    const std::size_t index = edges_.size() - 1;
    adjacency_[from].push_back(index);
    adjacency_[to].push_back(index);
    addResidual(index);
    return index;
}

void PoseGraph::withdrawEdge(std::size_t index) {
    PoseGraphEdge& e = edges_[index];
    if (!e.active)
        return;
    e.active = false;
    problem_->RemoveResidualBlock(static_cast<ceres::ResidualBlockId>(residuals_[index]));
    residuals_[index] = nullptr;
    costs_[index] = nullptr;  // freed by the problem
    losses_[index] = nullptr;
    for (std::size_t node : {e.from, e.to}) {
        auto& list = adjacency_[node];
        list.erase(std::remove(list.begin(), list.end(), index), list.end());
    }
}

double PoseGraph::chi2(std::size_t from, std::size_t to, const CPose2D& measurement,
                       const mrpt::math::CMatrixDouble33& covariance) const {
    const CPose2D error = CPose2D() - measurement + (pose(to) - pose(from));
    const Eigen::Vector3d e(error.x(), error.y(), mrpt::math::wrapToPi(error.phi()));
    return e.dot(covariance.asEigen().ldlt().solve(e));
}

double PoseGraph::chi2(std::size_t index) const {
    const PoseGraphEdge& e = edges_[index];
    return chi2(e.from, e.to, e.measurement, e.covariance);
}

double PoseGraph::totalChi2() const {
    double sum = 0;
    for (std::size_t e = 0; e < edges_.size(); ++e)
        if (edges_[e].active)
            sum += chi2(e);
    return sum;
}

void PoseGraph::transformNodes(const CPose2D& transform) {
    for (auto& p : poses_) {
        const CPose2D moved = transform + CPose2D(p[0], p[1], p[2]);
        p = {moved.x(), moved.y(), moved.phi()};
    }
}

mrpt::graphs::CNetworkOfPoses2DInf PoseGraph::network() const {
    mrpt::graphs::CNetworkOfPoses2DInf g;
    g.root = 0;
    for (std::size_t i = 0; i < poses_.size(); ++i)
        g.nodes[i] = pose(i);
    for (const PoseGraphEdge& e : edges_) {
        if (!e.active)
            continue;
        mrpt::math::CMatrixDouble33 information;
        information.asEigen() = e.covariance.asEigen().inverse();
        g.insertEdge(e.from, e.to, mrpt::poses::CPosePDFGaussianInf(e.measurement, information));
    }
    return g;
}

std::size_t PoseGraph::solve(ceres::Problem& problem, int maxIterations) {
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    // Eigen's own factorisation: CHOLMOD's threaded BLAS spent more time waking its threads
    // than factorising a 2D pose graph of a few thousand nodes (perf on intel).
    options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
    options.max_num_iterations = maxIterations;
    options.num_threads = 1;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    return summary.iterations.size();
}

std::size_t PoseGraph::solveWindow(std::size_t firstFree, int maxIterations) {
    ceres::Problem::Options o;  // borrows the cost and loss functions of problem_
    o.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    o.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem window(o);
    for (std::size_t node = firstFree; node < poses_.size(); ++node) {
        for (std::size_t e : adjacency_[node]) {
            const PoseGraphEdge& edge = edges_[e];
            // Each edge once: from the free node with the larger id.
            const std::size_t other = edge.from == node ? edge.to : edge.from;
            if (other >= firstFree && other > node)
                continue;
            window.AddResidualBlock(costs_[e], losses_[e], poses_[edge.from].data(),
                                    poses_[edge.to].data());
            if (other < firstFree)
                window.SetParameterBlockConstant(poses_[other].data());
        }
    }
    return solve(window, maxIterations);
}

OptimizationResult PoseGraph::optimize(int maxIterations, std::size_t firstFree) {
    OptimizationResult result;
    firstFree = std::max<std::size_t>(1, firstFree);
    if (poses_.size() <= firstFree)
        return result;
    const double start = io::threadCpuSeconds();
    result.chi2Before = totalChi2();
    result.iterations =
        firstFree > 1 ? solveWindow(firstFree, maxIterations) : solve(*problem_, maxIterations);
    for (auto& p : poses_)
        p[2] = mrpt::math::wrapToPi(p[2]);
    result.chi2After = totalChi2();
    result.seconds = io::threadCpuSeconds() - start;
    return result;
}

void PoseGraph::save(const std::string& path) const {
    const mrpt::graphs::CNetworkOfPoses2DInf g = network();
    io::writeFileAtomically(path, [&](const std::string& tmp) { g.saveToTextFile(tmp); });
}

}  // namespace toposlam::mapping
