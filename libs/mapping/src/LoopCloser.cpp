#include <mrpt/math/wrap2pi.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/mapping/LoopCloser.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>

namespace toposlam::mapping {

using mrpt::math::CMatrixDouble33;
using mrpt::poses::CPose2D;

namespace {
matching::GraphMatcherOptions withoutRetry(matching::GraphMatcherOptions o) {
    o.guessFreeRetry = false;  // a gated candidate that fails guided is not this loop
    return o;
}

/// Whether the two keyframes' lasers can see the same things: with less than a full circle
/// of view, sensors facing apart by more than half the aperture (plus margin) share little.
bool viewsOverlap(const Keyframe& a, const Keyframe& b, const PoseGraph& graph) {
    const double aperture = std::min(a.fieldOfView, b.fieldOfView);
    if (aperture >= 1.75 * M_PI)
        return true;
    // The sensors' headings, as the poses composed would give them, without composing: this
    // runs for every older keyframe at every new one, and a composition costs a sine and cosine.
    const double ha = graph.pose(a.id).phi() + a.sensorOnRobot.phi();
    const double hb = graph.pose(b.id).phi() + b.sensorOnRobot.phi();
    return std::abs(mrpt::math::wrapToPi(ha - hb)) <= 0.5 * aperture + M_PI / 8;
}

/// A loop's covariance plus the path's swung covariance (PathVariance::swung), both in the
/// current keyframe's frame.
CMatrixDouble33 withSwung(const CMatrixDouble33& loop, const PathVariance& v) {
    const PathVariance::Covariance& c = v.swung;
    CMatrixDouble33 out = loop;
    out(0, 0) += c.xx, out(1, 1) += c.yy, out(2, 2) += c.hh;
    out(0, 1) += c.xy, out(1, 0) += c.xy;
    out(0, 2) += c.xh, out(2, 0) += c.xh;
    out(1, 2) += c.yh, out(2, 1) += c.yh;
    return out;
}

/// Error of pose b against pose a: a^-1 (+) b as (distance, |angle|).
std::pair<double, double> disagreement(const CPose2D& a, const CPose2D& b) {
    const CPose2D e = b - a;
    return {e.norm(), std::abs(mrpt::math::wrapToPi(e.phi()))};
}
}  // namespace

LoopCloser::LoopCloser(const GraphSlamOptions& options,
                       const matching::GraphMatcherOptions& matcherOptions)
    : options_(options),
      uncertainty_(options.driftSigmaXY, options.driftSigmaPhi),
      pool_(options.loopThreads),
      guided_(pool_.size(), matching::GraphScanMatcher(withoutRetry(matcherOptions))),
      free_(pool_.size(), matching::GraphScanMatcher(matcherOptions)),
      olderReadings_(pool_.size()) {}

std::vector<std::size_t> LoopCloser::gatedCandidates(std::size_t current, std::size_t firstActive,
                                                     const std::vector<Keyframe>& keyframes,
                                                     const PoseGraph& graph) {
    const CPose2D& here = graph.pose(current);
    // Nearest first, as a heap: the gate usually fills from the few nearest, while the older
    // keyframes, and a full sort of them at every new one, grow with the log. Squared distances
    // order them as the distances do.
    std::vector<std::pair<double, std::size_t>>& near = nearFirst_;
    near.clear();
    for (std::size_t j = 0; j < firstActive && j < current; ++j) {
        if (keyframes[current].travelled - keyframes[j].travelled < options_.loopMinTravel)
            continue;
        const double dx = graph.pose(j).x() - here.x(), dy = graph.pose(j).y() - here.y();
        near.push_back({dx * dx + dy * dy, j});
    }
    const auto nearer = std::greater<std::pair<double, std::size_t>>();
    std::make_heap(near.begin(), near.end(), nearer);
    // Spread out so that look-alike places in the gate get tried as well. The path uncertainty
    // is searched only as far as the keyframes looked at (PathUncertainty).
    uncertainty_.start(graph, current);
    std::vector<std::size_t> chosen;
    for (auto end = near.end(); end != near.begin() && chosen.size() < options_.loopMaxCandidates;
         --end) {
        std::pop_heap(near.begin(), end, nearer);
        const std::size_t j = std::prev(end)->second;
        if (!viewsOverlap(keyframes[j], keyframes[current], graph))
            continue;
        const double d = std::hypot(graph.pose(j).x() - here.x(), graph.pose(j).y() - here.y());
        const PathVariance& v = uncertainty_.to(j);
        if (!v.reached ||
            d > options_.loopOverlapDistance + options_.loopGateSigmas * std::sqrt(v.at(d)))
            continue;
        const mrpt::poses::CPose2D candidate = graph.pose(j);
        const bool spaced = std::all_of(chosen.begin(), chosen.end(), [&](std::size_t c) {
            return std::hypot(graph.pose(c).x() - candidate.x(),
                              graph.pose(c).y() - candidate.y()) >= options_.loopCandidateSpacing;
        });
        if (spaced)
            chosen.push_back(j);
    }
    return chosen;
}

std::vector<std::size_t> LoopCloser::globalCandidates(
    std::size_t current, std::size_t firstActive, const std::vector<Keyframe>& keyframes,
    const std::vector<std::size_t>& exclude) const {
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t j = 0; j < firstActive && j < current; ++j) {
        if (keyframes[current].travelled - keyframes[j].travelled < options_.loopMinTravel)
            continue;
        if (std::find(exclude.begin(), exclude.end(), j) != exclude.end())
            continue;
        ranked.push_back(
            {signatureDistance(keyframes[current].signature, keyframes[j].signature), j});
    }
    const std::size_t k = std::min(options_.globalSearchCandidates, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + long(k), ranked.end());
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < k; ++i)
        out.push_back(ranked[i].second);
    return out;
}

std::optional<LoopCloser::Measurement> LoopCloser::verify(
    matching::GraphScanMatcher& matcher, const Keyframe& older,
    const matching::PolarScan& olderReadings, const Keyframe& current,
    const matching::PolarScan& currentReadings, const PoseGraph& graph, bool guided) const {
    // This runs on several threads at once: CPose2D caches its cosine and sine in mutable
    // members, so compose only this thread's copies, never the keyframes' shared poses.
    const CPose2D olderMount = older.sensorOnRobot, currentMount = current.sensorOnRobot;
    std::optional<CPose2D> guess;
    if (guided)  // current sensor in the older sensor's frame, as the graph has it
        guess = (graph.pose(current.id) + currentMount) - (graph.pose(older.id) + olderMount);
    const matching::MatchResult& m =
        matcher.match(olderReadings, older.features->features, currentReadings,
                      current.features->features, guess);
    if (!m.reliable())
        return std::nullopt;
    Measurement out;
    out.older = older.id;
    out.current = current.id;
    out.pose = olderMount + m.pose + (-currentMount);
    out.covariance = m.covariance;
    const double sxy = options_.loopMinSigmaXY * options_.loopMinSigmaXY;
    const double sphi = options_.loopMinSigmaPhi * options_.loopMinSigmaPhi;
    out.covariance(0, 0) += sxy, out.covariance(1, 1) += sxy, out.covariance(2, 2) += sphi;
    return out;
}

std::vector<std::optional<LoopCloser::Measurement>> LoopCloser::verifyAll(
    const std::vector<std::size_t>& candidates, std::size_t current,
    const matching::PolarScan& currentReadings, const std::vector<Keyframe>& keyframes,
    const PoseGraph& graph, bool guided) {
    std::vector<std::optional<Measurement>> out(candidates.size());
    std::vector<matching::GraphScanMatcher>& matchers = guided ? guided_ : free_;
    pool_.run(candidates.size(), [&](std::size_t k, std::size_t thread) {
        const Keyframe& older = keyframes[candidates[k]];
        matching::PolarScan& olderReadings = olderReadings_[thread];
        olderReadings.assign(*older.scan);
        out[k] = verify(matchers[thread], older, olderReadings, keyframes[current], currentReadings,
                        graph, guided);
    });
    return out;
}

std::vector<LoopCloser::Measurement> LoopCloser::consistentGated(
    const std::vector<Measurement>& matches, const PoseGraph& graph, SlamStatistics& stats) {
    // Where each match puts the current robot in the world: two clearly different places mean
    // the scans fit look-alike places, and nothing here says which is right.
    for (std::size_t a = 0; a < matches.size(); ++a)
        for (std::size_t b = a + 1; b < matches.size(); ++b) {
            if (!pairConsistent(matches[a], matches[b], graph)) {
                stats.loopsGateRejected += matches.size();
                return {};
            }
        }
    std::vector<Measurement> out;
    for (const Measurement& m : matches) {
        const PathVariance& v = uncertainty_.to(m.older);
        CMatrixDouble33 combined = m.covariance;
        const double d = m.pose.norm();
        combined(0, 0) += v.at(d), combined(1, 1) += v.at(d), combined(2, 2) += v.heading;
        const bool inGate = graph.chi2(m.older, m.current, m.pose, combined) <= options_.loopChi2;
        // Beyond it, a loop may still be off by what a heading error far along the chain does
        // to the current keyframe: a shift across the lever arm together with the same turn.
        const bool swungIn =
            !inGate && options_.loopGateLeverArm && swungByTurn(m, v, graph) &&
            graph.chi2(m.older, m.current, m.pose, withSwung(m.covariance, v)) <= options_.loopChi2;
        if (inGate || swungIn) {
            out.push_back(m);
            out.back().swungIn = swungIn;
        } else {
            ++stats.loopsGateRejected;
            if (options_.loopContestedSupport > 0)
                contested_.push_back(m);
        }
    }
    return out;
}

std::pair<double, double> LoopCloser::offGraph(const Measurement& m, const PoseGraph& graph) {
    return disagreement(m.pose, graph.pose(m.current) - graph.pose(m.older));
}

bool LoopCloser::swungByTurn(const Measurement& m, const PathVariance& v,
                             const PoseGraph& graph) const {
    // A heading error along the chain moves the current keyframe by at most its turn times the
    // chain's reach; what the gate allows covers the rest. A look-alike place one door along is
    // a shift without the turn, which a long chain's covariance (heading errors that cancel)
    // may still explain.
    const auto [shift, turn] = offGraph(m, graph);
    return shift <= turn * v.reach + std::sqrt(options_.loopChi2 * v.at(m.pose.norm()));
}

void LoopCloser::acceptContested(const std::vector<Keyframe>& keyframes, const PoseGraph& graph,
                                 std::vector<Measurement>& accepted, SlamStatistics& stats) {
    const std::size_t need = options_.loopContestedSupport;
    if (need == 0 || contested_.size() < need)
        return;
    std::vector<std::size_t> best;
    for (std::size_t a = 0; a < contested_.size(); ++a) {
        std::vector<std::size_t> group{a};
        for (std::size_t b = 0; b < contested_.size(); ++b)
            if (b != a && std::all_of(group.begin(), group.end(), [&](std::size_t g) {
                    return pairConsistent(contested_[g], contested_[b], graph);
                }))
                group.push_back(b);
        if (group.size() > best.size())
            best = std::move(group);
    }
    if (best.size() < need)
        return;
    // Several searches, and older keyframes from two or more visits of the place (runs of the
    // path more than loopMinTravel apart): one pass through a look-alike place (a parallel
    // corridor) gives as many agreeing matches as the robot takes keyframes there.
    std::vector<double> olderTravel, currentTravel;
    for (std::size_t i : best) {
        olderTravel.push_back(keyframes[contested_[i].older].travelled);
        currentTravel.push_back(keyframes[contested_[i].current].travelled);
    }
    std::sort(olderTravel.begin(), olderTravel.end());
    std::size_t visits = 1;
    for (std::size_t k = 1; k < olderTravel.size(); ++k)
        visits += olderTravel[k] - olderTravel[k - 1] > options_.loopMinTravel;
    const auto [first, last] = std::minmax_element(currentTravel.begin(), currentTravel.end());
    if (*last <= *first || visits < 2)
        return;
    // And a front end that doubts its own way from each older keyframe to the current one:
    // where every scan since was placed by ICP, the graph is as right as its covariances say,
    // and matches beyond the gate fit a look-alike place (an office entered by its back door).
    const auto doubted = [&](const Measurement& m) {
        return std::any_of(keyframes.begin() + long(m.older) + 1,
                           keyframes.begin() + long(m.current) + 1,
                           [](const Keyframe& k) { return k.frontEndDoubt; });
    };
    if (!std::all_of(best.begin(), best.end(),
                     [&](std::size_t i) { return doubted(contested_[i]); }))
        return;
    if (contradicted(best, keyframes, graph, accepted)) {
        std::sort(best.rbegin(), best.rend());
        for (std::size_t i : best)
            contested_.erase(contested_.begin() + long(i));
        return;
    }
    for (std::size_t i : best) {
        accepted.push_back(contested_[i]);
        accepted.back().contested = true;
    }
    stats.loopsContested += best.size();
    stats.loopsGateRejected -= best.size();  // counted when the gate rejected them
    contested_.clear();
}

bool LoopCloser::contradicted(const std::vector<std::size_t>& group,
                              const std::vector<Keyframe>& keyframes, const PoseGraph& graph,
                              const std::vector<Measurement>& accepted) const {
    // A loop the gate let through meanwhile, into the same stretch of the old path, that
    // disagrees with the group: the graph was right there, and the group fits a look-alike
    // place (offices along a corridor); it is dropped.
    const auto contradicts = [&](const Measurement& loop) {
        return std::any_of(group.begin(), group.end(), [&](std::size_t i) {
            const Measurement& m = contested_[i];
            return std::abs(keyframes[loop.older].travelled - keyframes[m.older].travelled) <=
                       options_.loopMinTravel &&
                   !pairConsistent(loop, m, graph);
        });
    };
    // So does an earlier loop through the gate into the same place that the group
    // contradicts by more than the path since could have drifted: next to a room visited
    // twice, a look-alike room gives agreeing matches from two visits, and the last loop that
    // placed the robot right may be several metres back. The same place: the same stretch of
    // the old path, or stretches that an accepted loop joins (not two passes of the old path
    // that only the graph's estimate puts together: after a front-end failure those are the
    // ones that disagree).
    const double stretch = options_.loopMinTravel;
    std::vector<std::vector<double>> joined(group.size());  // per member: travel joined to it
    for (const PoseGraphEdge& e : graph.edges()) {
        if (!e.active || e.kind != EdgeKind::Loop)
            continue;
        const double from = keyframes[e.from].travelled, to = keyframes[e.to].travelled;
        for (std::size_t g = 0; g < group.size(); ++g) {
            const double t = keyframes[contested_[group[g]].older].travelled;
            if (std::abs(from - t) <= stretch)
                joined[g].push_back(to);
            if (std::abs(to - t) <= stretch)
                joined[g].push_back(from);
        }
    }
    const auto contradictsEarlier = [&](const Measurement& loop) {
        const double t = keyframes[loop.older].travelled;
        for (std::size_t g = 0; g < group.size(); ++g) {
            const Measurement& m = contested_[group[g]];
            const bool samePlace = std::abs(t - keyframes[m.older].travelled) <= stretch ||
                                   std::any_of(joined[g].begin(), joined[g].end(), [&](double u) {
                                       return std::abs(t - u) <= stretch;
                                   });
            if (!samePlace)
                continue;
            const auto [d, phi] = cycleDisagreement(loop, m, graph);
            const auto [dTolerance, phiTolerance] =
                driftTolerance(keyframes[loop.current], keyframes[m.current]);
            if (d > dTolerance || phi > phiTolerance)
                return true;
        }
        return false;
    };
    return std::any_of(recent_.begin(), recent_.end(), contradicts) ||
           std::any_of(accepted.begin(), accepted.end(), contradicts) ||
           std::any_of(throughGate_.begin(), throughGate_.end(), contradictsEarlier);
}

bool LoopCloser::agreesWithGraph(const Measurement& m, const PoseGraph& graph) const {
    return graph.chi2(m.older, m.current, m.pose, m.covariance) <= options_.loopChi2;
}

void LoopCloser::acceptWithSupport(const Measurement& m, const PoseGraph& graph,
                                   std::vector<Measurement>& accepted) {
    // Support is another loop from another keyframe that closes the same cycle consistently.
    const auto supports = [&](const Measurement& o) {
        return o.current != m.current && pairConsistent(o, m, graph);
    };
    const auto pending = std::find_if(pending_.begin(), pending_.end(), supports);
    if (pending != pending_.end()) {
        accepted.push_back(*pending);
        pending_.erase(pending);
        accepted.push_back(m);
    } else if (std::any_of(recent_.begin(), recent_.end(), supports)) {
        accepted.push_back(m);
    } else {
        pending_.push_back(m);
    }
}

std::pair<double, double> LoopCloser::cycleDisagreement(const Measurement& a, const Measurement& b,
                                                        const PoseGraph& graph) const {
    // b's current keyframe in a's older frame, two ways round the cycle:
    // a's loop then the graph from a.current to b.current, or the graph from a.older to
    // b.older then b's loop.
    const CPose2D viaA = a.pose + (graph.pose(b.current) - graph.pose(a.current));
    const CPose2D viaB = (graph.pose(b.older) - graph.pose(a.older)) + b.pose;
    return disagreement(viaA, viaB);
}

bool LoopCloser::pairConsistent(const Measurement& a, const Measurement& b,
                                const PoseGraph& graph) const {
    const auto [d, phi] = cycleDisagreement(a, b, graph);
    return d <= options_.loopPairTolerance && phi <= options_.loopPairAngleTolerance;
}

std::pair<double, double> LoopCloser::driftTolerance(const Keyframe& a, const Keyframe& b) const {
    // The pair tolerances plus loopGateSigmas of the drift model over the path between them.
    const double length = std::abs(b.travelled - a.travelled);
    const double turn = std::abs(b.turned - a.turned);
    const double k = options_.loopGateSigmas;
    return {
        options_.loopPairTolerance + k * options_.driftSigmaXY * std::sqrt(length),
        options_.loopPairAngleTolerance +
            k * std::sqrt(options_.driftSigmaPhi * options_.driftSigmaPhi * length +
                          options_.driftSigmaPhiPerTurn * options_.driftSigmaPhiPerTurn * turn)};
}

void LoopCloser::accept(const Measurement& m, PoseGraph& graph, LoopClosureOutcome& outcome,
                        SlamStatistics& stats) {
    const auto [d, phi] = offGraph(m, graph);
    outcome.maxDistanceError = std::max(outcome.maxDistanceError, d);
    outcome.maxAngleError = std::max(outcome.maxAngleError, phi);
    graph.addEdge(m.older, m.current, m.pose, m.covariance, EdgeKind::Loop,
                  !m.contested && !m.swungIn);
    ++outcome.accepted;
    ++stats.loopsAccepted;
    stats.loopsSwungIn += m.swungIn;
    recent_.push_back(m);
    if (!m.contested && options_.loopContestedSupport > 0)
        throughGate_.push_back(m);  // evidence against contested groups
}

LoopClosureOutcome LoopCloser::closeLoops(std::size_t current,
                                          const matching::PolarScan& currentReadings,
                                          std::size_t firstActive,
                                          const std::vector<Keyframe>& keyframes, PoseGraph& graph,
                                          SlamStatistics& stats) {
    const double start = io::threadCpuSeconds();
    const double workersBefore = pool_.workerCpuSeconds();
    LoopClosureOutcome outcome;
    while (!recent_.empty() && recent_.front().current + options_.loopConfirmWindow < current)
        recent_.pop_front();
    while (!pending_.empty() && pending_.front().current + options_.loopConfirmWindow < current) {
        ++stats.loopsUnconfirmed;
        pending_.pop_front();
    }
    while (!contested_.empty() && contested_.front().current + options_.loopConfirmWindow < current)
        contested_.pop_front();
    // Evidence for contested groups (acceptContested): the loop that last placed the robot
    // right lies where it left the mapped place, and a look-alike is met within about two
    // loopMinTravel of that; much farther back, a front-end failure in between (what the
    // contested rule recovers from) becomes the likelier story.
    while (!throughGate_.empty() &&
           keyframes[throughGate_.front().current].travelled + 2 * options_.loopMinTravel <
               keyframes[current].travelled)
        throughGate_.pop_front();
    std::vector<Measurement> accepted;
    const std::vector<std::size_t> gated = gatedCandidates(current, firstActive, keyframes, graph);
    std::vector<Measurement> matches;
    for (const auto& m : verifyAll(gated, current, currentReadings, keyframes, graph, true)) {
        ++stats.loopCandidates;
        if (m)
            matches.push_back(*m);
        else
            ++stats.loopsUnmatched;
    }
    const std::vector<Measurement> consistent = consistentGated(matches, graph, stats);
    // Loops that agree with the graph cannot hurt; a loop that corrects it needs a second,
    // independent match that agrees with it: from another older keyframe now, or from a
    // later keyframe (pending).
    const bool corroborated = consistent.size() >= 2;
    for (const Measurement& m : consistent) {
        if (corroborated || agreesWithGraph(m, graph))
            accepted.push_back(m);
        else
            acceptWithSupport(m, graph, accepted);
    }
    acceptContested(keyframes, graph, accepted, stats);
    if (options_.globalSearchEvery > 0 && current % options_.globalSearchEvery == 0) {
        ++stats.globalSearches;
        const std::vector<std::size_t> global =
            globalCandidates(current, firstActive, keyframes, gated);
        for (const auto& m : verifyAll(global, current, currentReadings, keyframes, graph, false)) {
            ++stats.loopCandidates;
            if (m) {
                ++stats.globalHypotheses;
                const std::size_t before = accepted.size();
                acceptWithSupport(*m, graph, accepted);
                stats.globalConfirmed += accepted.size() - before;
            } else {
                ++stats.loopsUnmatched;
            }
        }
    }
    for (const Measurement& m : accepted)
        accept(m, graph, outcome, stats);
    const double offloaded = pool_.workerCpuSeconds() - workersBefore;
    stats.loopSeconds += io::threadCpuSeconds() - start + offloaded;
    stats.offloadedSeconds += offloaded;
    return outcome;
}

void LoopCloser::finish(const std::vector<Keyframe>& keyframes, const PoseGraph& graph,
                        SlamStatistics& stats) {
    // A loop found in the log's last keyframes had no later keyframe to confirm it: one match
    // cannot tell the place from a look-alike, so it stays out, and the summary says so.
    for (const Measurement& m : pending_) {
        ++stats.loopsUnconfirmed;
        const auto [d, phi] = offGraph(m, graph);
        if (d <= options_.optimizeGlobalDistance && phi <= options_.optimizeGlobalAngle)
            continue;
        ++stats.loopsOpenAtEnd;
        if (d > stats.largestOpenLoop.distance)
            stats.largestOpenLoop = {keyframes[m.older].scanIndex, keyframes[m.current].scanIndex,
                                     d, phi};
    }
    pending_.clear();
}

bool LoopCloser::withdrawWorstOutlier(PoseGraph& graph, SlamStatistics& stats) const {
    double worst = options_.loopWithdrawChi2;
    std::optional<std::size_t> worstEdge;
    for (std::size_t e = 0; e < graph.edges().size(); ++e) {
        const PoseGraphEdge& edge = graph.edges()[e];
        if (!edge.active || edge.kind != EdgeKind::Loop)
            continue;
        const double c = graph.chi2(e);
        if (c > worst)
            worst = c, worstEdge = e;
    }
    if (!worstEdge)
        return false;
    graph.withdrawEdge(*worstEdge);
    ++stats.loopsWithdrawn;
    return true;
}

}  // namespace toposlam::mapping
