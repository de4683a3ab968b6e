#include <mrpt/math/wrap2pi.h>
#include <toposlam/mapping/PathUncertainty.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace toposlam::mapping {

namespace {
/// m: heading variance is weighed as position variance this far away when choosing chains.
constexpr double kLeverArm = 5.0;
}  // namespace

PathUncertainty::PathUncertainty(double driftSigmaXY, double driftSigmaPhi,
                                 double driftSigmaPhiPerTurn)
    : driftXY_(driftSigmaXY), driftPhi_(driftSigmaPhi), driftTurn_(driftSigmaPhiPerTurn) {}

const std::vector<PathVariance>& PathUncertainty::from(const PoseGraph& graph, std::size_t source) {
    const std::size_t n = graph.nodeCount();
    variance_.assign(n, PathVariance());
    cost_.assign(n, std::numeric_limits<double>::infinity());
    heap_.clear();
    cost_[source] = 0;
    variance_[source].reached = true;
    heap_.push_back({0.0, source});
    const auto later = std::greater<std::pair<double, std::size_t>>();
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), later);
        const auto [cost, node] = heap_.back();
        heap_.pop_back();
        if (cost > cost_[node])
            continue;  // stale entry
        for (std::size_t e : graph.edgesAt(node)) {
            const PoseGraphEdge& edge = graph.edges()[e];
            const std::size_t next = edge.from == node ? edge.to : edge.from;
            const double length = edge.measurement.norm();
            const double edgePosition = std::max({edge.covariance(0, 0), edge.covariance(1, 1),
                                                  driftXY_ * driftXY_ * length * length});
            const double edgeHeading =
                std::max(edge.covariance(2, 2), driftPhi_ * driftPhi_ * length * length);
            PathVariance v = variance_[node];
            v.position += edgePosition;
            v.heading += edgeHeading;
            const double c = v.position + v.heading * kLeverArm * kLeverArm;
            if (c < cost_[next]) {
                cost_[next] = c;
                v.reached = true;
                variance_[next] = v;
                heap_.push_back({c, next});
                std::push_heap(heap_.begin(), heap_.end(), later);
            }
        }
    }
    return variance_;
}

}  // namespace toposlam::mapping
