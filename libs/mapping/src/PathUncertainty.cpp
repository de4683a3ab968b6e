#include <mrpt/math/wrap2pi.h>
#include <toposlam/mapping/PathUncertainty.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace toposlam::mapping {

namespace {
/// m: heading variance is weighed as position variance this far away when choosing chains.
constexpr double kLeverArm = 5.0;
}  // namespace

PathUncertainty::PathUncertainty(double driftSigmaXY, double driftSigmaPhi)
    : driftXY_(driftSigmaXY), driftPhi_(driftSigmaPhi) {}

void PathUncertainty::cacheNewEdges(const PoseGraph& graph) {
    // Edges are only ever appended (a withdrawn one leaves the adjacency lists), so each
    // edge's contribution is computed once.
    const std::vector<PoseGraphEdge>& edges = graph.edges();
    if (edges.size() < steps_.size())
        steps_.clear();  // another graph
    for (std::size_t e = steps_.size(); e < edges.size(); ++e) {
        const PoseGraphEdge& edge = edges[e];
        const double length = edge.measurement.norm();
        Step s;
        s.from = edge.from;
        s.to = edge.to;
        s.position = std::max(
            {edge.covariance(0, 0), edge.covariance(1, 1), driftXY_ * driftXY_ * length * length});
        s.heading = std::max(edge.covariance(2, 2), driftPhi_ * driftPhi_ * length * length);
        steps_.push_back(s);
    }
}

void PathUncertainty::start(const PoseGraph& graph, std::size_t source) {
    cacheNewEdges(graph);
    graph_ = &graph;
    const std::size_t n = graph.nodeCount();
    variance_.assign(n, PathVariance());
    covariance_.assign(n, PoseCovariance());
    source_ = source;
    sourceCos_ = std::cos(graph.pose(source).phi());
    sourceSin_ = std::sin(graph.pose(source).phi());
    cost_.assign(n, std::numeric_limits<double>::infinity());
    settled_.assign(n, 0);
    heap_.clear();
    cost_[source] = 0;
    variance_[source].reached = true;
    heap_.push_back({0.0, source});
}

void PathUncertainty::compound(std::size_t node, std::size_t next, const Step& step) {
    // next = node (+) step: a heading error at `node` moves `next` by it times the lever
    // perpendicular to node -> next (u); the step adds its own variances.
    const PoseCovariance& a = covariance_[node];
    PoseCovariance& b = covariance_[next];
    const mrpt::poses::CPose2D& pa = graph_->pose(node);
    const mrpt::poses::CPose2D& pb = graph_->pose(next);
    const double ux = pa.y() - pb.y(), uy = pb.x() - pa.x();
    b.xx = a.xx + 2 * ux * a.xh + ux * ux * a.hh + step.position;
    b.yy = a.yy + 2 * uy * a.yh + uy * uy * a.hh + step.position;
    b.xy = a.xy + ux * a.yh + uy * a.xh + ux * uy * a.hh;
    b.xh = a.xh + ux * a.hh;
    b.yh = a.yh + uy * a.hh;
    b.hh = a.hh + step.heading;
    // The source seen from `next`: next's heading error swings it by the lever next -> source
    // (v) and turns it alike; then turned into the source's frame.
    const mrpt::poses::CPose2D& ps = graph_->pose(source_);
    const double vx = pb.y() - ps.y(), vy = ps.x() - pb.x();
    const double sxx = b.xx + 2 * vx * b.xh + vx * vx * b.hh;
    const double syy = b.yy + 2 * vy * b.yh + vy * vy * b.hh;
    const double sxy = b.xy + vx * b.yh + vy * b.xh + vx * vy * b.hh;
    const double sxh = b.xh + vx * b.hh, syh = b.yh + vy * b.hh;
    const double c = sourceCos_, s = sourceSin_;
    PathVariance::Covariance& r = variance_[next].swung;
    r.xx = c * c * sxx + 2 * c * s * sxy + s * s * syy;
    r.yy = s * s * sxx - 2 * c * s * sxy + c * c * syy;
    r.xy = -c * s * sxx + (c * c - s * s) * sxy + c * s * syy;
    r.xh = c * sxh + s * syh;
    r.yh = -s * sxh + c * syh;
    r.hh = b.hh;
    variance_[next].reach =
        std::max(variance_[node].reach, std::hypot(pb.x() - ps.x(), pb.y() - ps.y()));
}

bool PathUncertainty::settleNext() {
    const auto later = std::greater<std::pair<double, std::size_t>>();
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), later);
        const auto [cost, node] = heap_.back();
        heap_.pop_back();
        if (cost > cost_[node])
            continue;  // stale entry
        settled_[node] = 1;
        const PathVariance here = variance_[node];
        for (std::size_t e : graph_->edgesAt(node)) {
            const Step& step = steps_[e];
            const std::size_t next = step.from == node ? step.to : step.from;
            const double position = here.position + step.position;
            const double heading = here.heading + step.heading;
            const double c = position + heading * kLeverArm * kLeverArm;
            if (c < cost_[next]) {
                cost_[next] = c;
                PathVariance& v = variance_[next];
                v.position = position;
                v.heading = heading;
                v.reached = true;
                compound(node, next, step);  // v.swung, v.reach
                heap_.push_back({c, next});
                std::push_heap(heap_.begin(), heap_.end(), later);
            }
        }
        return true;
    }
    return false;
}

const PathVariance& PathUncertainty::to(std::size_t node) {
    while (!settled_[node] && settleNext()) {
    }
    return variance_[node];  // not settled: unreached (nothing left to settle)
}

const std::vector<PathVariance>& PathUncertainty::from(const PoseGraph& graph, std::size_t source) {
    start(graph, source);
    while (settleNext()) {
    }
    return variance_;
}

}  // namespace toposlam::mapping
