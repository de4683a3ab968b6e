#pragma once
// How uncertain the relative pose of the current keyframe and each earlier one is, propagated
// through the pose graph: the least uncertain chain of edges between the two. Along a chain
// the variances of position and heading add up (a random walk); the heading variance v_phi
// at the source turns into a position variance v_phi d^2 at distance d. Each edge contributes its
// own covariance, but at least (a l)^2 and (b l)^2 for its length l: scan matching's covariance
// ignores the map's own errors, which are what makes a trajectory drift. (This is not the random
// walk a^2 l, b^2 l + c^2 t of LoopCloser's pair tolerances: with keyframes 0.3 m apart that
// walk makes the gate 1.8 times as wide, and it let loops into a look-alike office, ATE 1.0 m
// instead of under 0.1 m in GraphSlam.NoLoopIntoTheOfficeNextToOneVisitedThreeTimes.)
// After a loop closure the chain through the loop edge is short, so the gate shrinks there.
// Along the same chain the search also carries the full covariance (first-order pose
// compounding), in which each edge's heading variance swings the rest of the chain about it:
// seen from an older keyframe, the source's position then varies by what heading errors far
// out along the chain do to it. Back round a ring, where the two keyframes are close and the
// chain went 20 m away, that is several times position + heading d^2, and it comes with the
// heading error that caused it (PathVariance::swung).
// Dijkstra with a scalar cost (position variance + heading variance times a lever arm of
// kLeverArm), no allocation after the first query. It runs lazily: to(node) carries the
// search on only until that node is settled, and keyframes are settled in order of cost, so a
// caller that asks for the nearby keyframes first (the loop closer: a revisited place is tied to
// its earlier visits by loops) explores only the graph around them. The answers are the same
// as those of a full search (from()).
#include <toposlam/mapping/PoseGraph.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace toposlam::mapping {

struct PathVariance {
    double position = 0;  ///< m^2, isotropic
    double heading = 0;   ///< rad^2
    /// Covariance of the source's pose as seen from the node, each edge's heading variance
    /// taken with its lever arm to the source (first-order pose compounding), in the source's
    /// own frame, where a loop's chi-square measures its error (m^2, m rad, rad^2). A heading
    /// error along the chain moves the source across its lever arm and turns it alike: the
    /// position and heading errors are correlated, and a loop that is off by a shift without
    /// the turn that would explain it stays far outside.
    struct Covariance {
        double xx = 0, xy = 0, yy = 0, xh = 0, yh = 0, hh = 0;
    } swung;
    /// m: the farthest the chain went from the source, the longest lever arm a heading error
    /// along it has.
    double reach = 0;
    bool reached = false;
    /// Position variance (m^2) of a point at distance d (m) from the source.
    double at(double d) const { return position + heading * d * d; }
};

class PathUncertainty {
  public:
    /// a (m per m) and b (rad per m): an edge of length l adds at least (a l)^2 and (b l)^2.
    PathUncertainty(double driftSigmaXY, double driftSigmaPhi);
    /// Starts a search from `source` through the active edges of `graph`, which must not
    /// change until the last to() of this search.
    void start(const PoseGraph& graph, std::size_t source);
    /// Variances of `node`'s pose relative to the source (reached = false: no chain of active
    /// edges joins them), settling the nodes the search has not settled yet up to it.
    const PathVariance& to(std::size_t node);
    /// Variances of every node's pose relative to `source` (the whole search).
    const std::vector<PathVariance>& from(const PoseGraph& graph, std::size_t source);

  private:
    /// What an edge adds to a chain: its variances, at least the drift model's.
    struct Step {
        std::size_t from = 0, to = 0;
        double position = 0, heading = 0;  ///< m^2, rad^2
    };
    void cacheNewEdges(const PoseGraph& graph);
    /// Settles the cheapest node not settled yet; false when none is left.
    bool settleNext();

    double driftXY_, driftPhi_;
    std::vector<Step> steps_;           // by edge index
    const PoseGraph* graph_ = nullptr;  // of the current search
    /// Covariance of a node's pose relative to the source, world axes (m^2, m rad, rad^2).
    struct PoseCovariance {
        double xx = 0, xy = 0, yy = 0, xh = 0, yh = 0, hh = 0;
    };
    /// `next`'s covariance, and the source's swung covariance seen from it and the chain's
    /// reach, reached from the settled `node` by `step`.
    void compound(std::size_t node, std::size_t next, const Step& step);

    std::vector<PathVariance> variance_;
    std::vector<PoseCovariance> covariance_;
    std::size_t source_ = 0;
    double sourceCos_ = 1, sourceSin_ = 0;  // of the source's heading: turns `swung` into its frame
    std::vector<double> cost_;
    std::vector<std::uint8_t> settled_;
    std::vector<std::pair<double, std::size_t>> heap_;
};

}  // namespace toposlam::mapping
