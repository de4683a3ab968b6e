#pragma once
// Loop closure for each new keyframe: which older keyframes may show the same place, whether
// they do, and whether the graph can believe it.
//  - Gated candidates: older keyframes (beyond loopMinTravel of travel, outside the active
//    submaps) whose estimated position is within loopOverlapDistance + loopGateSigmas sigma
//    of the current one, sigma from the relative uncertainty propagated through the graph
//    (PathUncertainty). The nearest are verified, at least loopCandidateSpacing apart.
//  - Guess-free search every globalSearchEvery keyframes, against the keyframes outside the
//    gate whose scan signature is most similar (the graph matcher needs no guess: that is
//    what finds a loop after drift larger than any gate).
//  - Verification: the graph matcher (reliable status, its ambiguity margin), guided by the
//    graph's relative pose for gated candidates, guess-free for the others.
//  - Consistency: a gated match must agree with the graph within the chi-square bound of
//    their combined covariance (with loopGateLeverArm, the default, also one that agrees within
//    that bound once the path's covariance carries each heading error swung by its lever arm,
//    PathVariance::swung, and that is off by a turn and no more shift than the turn makes
//    across the chain, swungByTurn: back round a building; added without the robust loss);
//    when two reliable matches inside the gate put the robot in clearly different places
//    (identical rooms), all of them are rejected. A match that the graph already agrees with
//    (within the match's own covariance) is accepted; one that would correct the graph needs
//    support: a second match to another older keyframe in the same search, or a loop within
//    loopConfirmWindow keyframes that agrees with it around their common cycle (pairwise
//    consistency); guess-free matches always need support. After optimisation the builder
//    withdraws loops whose residual still exceeds a far looser bound, loopWithdrawChi2
//    (withdrawWorstOutlier).
//  - Contested matches (loopContestedSupport > 0, the default): a front-end failure (a step
//    neither ICP nor the graph matcher could place, a laser dropout while the wheels slip) can
//    put the robot farther off than the drift model's gate allows, and then every right loop is
//    rejected. Gate-rejected matches are kept for loopConfirmWindow keyframes;
//    loopContestedSupport of them that agree pairwise, from two or more searches and against older
//    keyframes of two or more visits of the place, are accepted together, without the robust loss
//    (through it, a few loops many sigma off would hardly pull). Matches into a look-alike place (a
//    parallel corridor, the office next door) agree with each other too: one pass through it gives
//    as many as the robot takes keyframes there, hence the two visits; and they are dropped when a
//    loop that passed the gate meanwhile, into the same stretch of the old path, disagrees with
//    them (the graph was right there), or when one that passed it within the last 2 loopMinTravel
//    of the path, into the same place (the same stretch, or one an accepted loop joins to it),
//    disagrees by more than the drift model allows over the path since: the office next to one
//    visited twice, met a few metres after the loop in the corridor that placed the robot right.
//    Above all, a group is taken only past a keyframe the front end doubts (Keyframe::
//    frontEndDoubt: placed by the graph matcher or the odometry) between each of its older
//    keyframes and the current one: where ICP placed every scan, the graph is as right as its
//    covariances say, and matches beyond the gate fit a look-alike (an office entered by its
//    back door after 30 m of corridors: GraphSlam.NoLoopIntoALookAlikeOfficeThroughItsBackDoor).
//  Candidates are verified on loopThreads threads, one graph matcher each; the matcher is a
//  pure function of its inputs, so the loops found do not depend on the number of threads.
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/mapping/Keyframe.h>
#include <toposlam/mapping/PathUncertainty.h>
#include <toposlam/mapping/PoseGraph.h>
#include <toposlam/mapping/SlamStatistics.h>
#include <toposlam/mapping/WorkerPool.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <cstddef>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

namespace toposlam::mapping {

struct LoopClosureOutcome {
    std::size_t accepted = 0;
    /// Largest disagreement of an accepted loop with the graph before optimising (m, rad).
    double maxDistanceError = 0, maxAngleError = 0;
};

class LoopCloser {
  public:
    LoopCloser(const GraphSlamOptions& options,
               const matching::GraphMatcherOptions& matcherOptions);

    /// Looks for loops of keyframe `current` against keyframes older than `firstActive` (the
    /// first keyframe of the active submaps) and adds the accepted ones to `graph`.
    /// `currentReadings`: keyframe `current`'s readings (sensor frame; keyframes do not keep
    /// theirs, Keyframe::scan).
    LoopClosureOutcome closeLoops(std::size_t current, const matching::PolarScan& currentReadings,
                                  std::size_t firstActive, const std::vector<Keyframe>& keyframes,
                                  PoseGraph& graph, SlamStatistics& stats);

    /// At the end of the log: the loops still awaiting support are unconfirmed; those that
    /// would move the graph by more than optimizeGlobalDistance or optimizeGlobalAngle are
    /// counted as open (SlamStatistics::loopsOpenAtEnd, largestOpenLoop).
    void finish(const std::vector<Keyframe>& keyframes, const PoseGraph& graph,
                SlamStatistics& stats);

    /// After optimisation: withdraws the loop edge with the largest chi-square above
    /// loopWithdrawChi2; true when one was withdrawn (optimise again).
    bool withdrawWorstOutlier(PoseGraph& graph, SlamStatistics& stats) const;

  private:
    struct Measurement {
        std::size_t older = 0, current = 0;
        mrpt::poses::CPose2D pose;  ///< current robot in the older robot frame
        mrpt::math::CMatrixDouble33 covariance;
        /// Accepted beyond the gate on agreeing evidence: added without the robust loss.
        bool contested = false;
        /// Let in by the gate's lever arm only (loop_gate_lever_arm): added without the robust
        /// loss too, under which a correction many of its own sigmas long would hardly pull.
        bool swungIn = false;
    };
    /// Older keyframes to verify: in the Mahalanobis gate, nearest first, spaced; the path
    /// uncertainty is searched only as far as the keyframes looked at (and kept in uncertainty_
    /// for consistentGated).
    std::vector<std::size_t> gatedCandidates(std::size_t current, std::size_t firstActive,
                                             const std::vector<Keyframe>& keyframes,
                                             const PoseGraph& graph);
    std::vector<std::size_t> globalCandidates(std::size_t current, std::size_t firstActive,
                                              const std::vector<Keyframe>& keyframes,
                                              const std::vector<std::size_t>& exclude) const;
    /// Matches `current` against `older`, whose readings (sensor frames) are given.
    std::optional<Measurement> verify(matching::GraphScanMatcher& matcher, const Keyframe& older,
                                      const matching::PolarScan& olderReadings,
                                      const Keyframe& current,
                                      const matching::PolarScan& currentReadings,
                                      const PoseGraph& graph, bool guided) const;
    /// verify() of every candidate against `current`, spread over the pool's threads (each
    /// rebuilds its candidates' readings from their scans, Keyframe::scan); out[k] is
    /// candidate k's match.
    std::vector<std::optional<Measurement>> verifyAll(const std::vector<std::size_t>& candidates,
                                                      std::size_t current,
                                                      const matching::PolarScan& currentReadings,
                                                      const std::vector<Keyframe>& keyframes,
                                                      const PoseGraph& graph, bool guided);
    /// Gated matches that agree with the graph (none when they contradict each other); the
    /// ones the gate rejects go to contested_.
    std::vector<Measurement> consistentGated(const std::vector<Measurement>& matches,
                                             const PoseGraph& graph, SlamStatistics& stats);
    /// How far (m, |rad|) `m` is off the graph's relative pose of its two keyframes.
    static std::pair<double, double> offGraph(const Measurement& m, const PoseGraph& graph);
    /// The disagreement of `m` with the graph is a turn and the shift that turn makes across
    /// the chain's reach (PathVariance::reach), plus no more than the gate allows: what a
    /// heading error along the chain does (loop_gate_lever_arm).
    bool swungByTurn(const Measurement& m, const PathVariance& v, const PoseGraph& graph) const;
    /// Accepts (into `accepted`) the largest set of contested matches that agree pairwise
    /// when it has loopContestedSupport members, from several searches, against older
    /// keyframes of two or more visits, and no gated loop contradicts it.
    void acceptContested(const std::vector<Keyframe>& keyframes, const PoseGraph& graph,
                         std::vector<Measurement>& accepted, SlamStatistics& stats);
    /// True when a loop through the gate disagrees with the contested matches `group`
    /// (indices into contested_): the guard against look-alike places (above).
    bool contradicted(const std::vector<std::size_t>& group, const std::vector<Keyframe>& keyframes,
                      const PoseGraph& graph, const std::vector<Measurement>& accepted) const;
    /// True when the graph already agrees with the loop within the loop's own covariance.
    bool agreesWithGraph(const Measurement& m, const PoseGraph& graph) const;
    /// Accepts `m` (into `accepted`) when another loop from another keyframe supports it
    /// (pending or recently accepted), else keeps it pending.
    void acceptWithSupport(const Measurement& m, const PoseGraph& graph,
                           std::vector<Measurement>& accepted);
    /// How far apart (m, rad) the two loops put b's current keyframe, around the cycle they
    /// close with the graph.
    std::pair<double, double> cycleDisagreement(const Measurement& a, const Measurement& b,
                                                const PoseGraph& graph) const;
    /// True when the two loops agree around that cycle (loopPairTolerance, ...AngleTolerance).
    bool pairConsistent(const Measurement& a, const Measurement& b, const PoseGraph& graph) const;
    /// The pair tolerances (m, rad) widened by loopGateSigmas of the drift model over the
    /// path between keyframes a and b.
    std::pair<double, double> driftTolerance(const Keyframe& a, const Keyframe& b) const;
    void accept(const Measurement& m, PoseGraph& graph, LoopClosureOutcome& outcome,
                SlamStatistics& stats);

    const GraphSlamOptions& options_;
    PathUncertainty uncertainty_;
    WorkerPool pool_;
    std::vector<matching::GraphScanMatcher> guided_, free_;  // one of each per pool thread
    std::vector<matching::PolarScan> olderReadings_;         // per pool thread (reused)
    // The gate's candidates of the current query: a min-heap of (squared distance, keyframe),
    // popped nearest first (reused).
    std::vector<std::pair<double, std::size_t>> nearFirst_;
    std::deque<Measurement> pending_;    // guess-free matches awaiting confirmation
    std::deque<Measurement> recent_;     // accepted loops, for confirming guess-free ones
    std::deque<Measurement> contested_;  // gated matches the gate rejected, recent ones
    // Loops accepted through the gate over the last 2 loopMinTravel of the path.
    std::deque<Measurement> throughGate_;
};

}  // namespace toposlam::mapping
