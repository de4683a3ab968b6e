#include <mrpt/math/wrap2pi.h>
#include <toposlam/io/CpuTime.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

namespace toposlam::matching {

using mrpt::poses::CPose2D;

const char* toString(MatchStatus s) {
    switch (s) {
        case MatchStatus::Matched:
            return "matched";
        case MatchStatus::TooFewFeatures:
            return "too few features";
        case MatchStatus::NoConsensus:
            return "no consensus";
        case MatchStatus::PoorFit:
            return "poor fit";
        case MatchStatus::Degenerate:
            return "degenerate";
        case MatchStatus::Ambiguous:
            return "ambiguous";
    }
    return "?";
}

using io::threadCpuSeconds;

GraphScanMatcher::GraphScanMatcher(const GraphMatcherOptions& options) : options_(options) {}

void GraphScanMatcher::buildCandidates(const std::optional<CPose2D>& guess) {
    candidates_.clear();
    scored_.clear();
    const double c = guess ? std::cos(guess->phi()) : 1.0, s = guess ? std::sin(guess->phi()) : 0.0;
    for (std::uint32_t i = 0; i < current_.size(); ++i) {
        const SegmentNode& cn = current_.node(i);
        double mx = 0, my = 0, window = 0;
        if (guess) {
            mx = guess->x() + c * cn.midpoint.x - s * cn.midpoint.y;
            my = guess->y() + s * cn.midpoint.x + c * cn.midpoint.y;
            // A rotation error moves far points further: widen the window with the range.
            window = options_.guessTranslationWindow + std::hypot(cn.midpoint.x, cn.midpoint.y) *
                                                           std::sin(options_.guessRotationWindow);
        }
        for (std::uint32_t a = 0; a < reference_.size(); ++a) {
            const SegmentNode& rn = reference_.node(a);
            if (guess) {
                if (std::abs(mrpt::math::wrapToPi(cn.heading + guess->phi() - rn.heading)) >
                    options_.guessRotationWindow)
                    continue;
                // Distance of the predicted midpoint to the reference segment.
                const double t = std::clamp(
                    (mx - rn.start.x) * rn.direction.x + (my - rn.start.y) * rn.direction.y, 0.0,
                    rn.length);
                const double d = std::hypot(mx - rn.start.x - t * rn.direction.x,
                                            my - rn.start.y - t * rn.direction.y);
                if (d > window + 0.5 * cn.length)
                    continue;
            } else {
                const double ratio =
                    std::min(cn.length, rn.length) / std::max(cn.length, rn.length);
                if (ratio < options_.minLengthRatio)
                    continue;
            }
            candidates_.push_back(swapped_ ? Assignment{a, i} : Assignment{i, a});
            scored_.push_back({i, a, 0.0});
        }
    }
}

void GraphScanMatcher::buildPool() {
    // Greedy one-to-one matches plus, per observed segment, its most probable alternatives.
    pool_.clear();
    for (const AssignedPair& g : greedy_.pairs())
        pool_.push_back(scored_[g.candidate]);
    std::sort(scored_.begin(), scored_.end(),
              [](const ScoredAssignment& a, const ScoredAssignment& b) {
                  if (a.current != b.current)
                      return a.current < b.current;
                  if (a.probability != b.probability)
                      return a.probability > b.probability;
                  return a.reference < b.reference;
              });
    std::size_t taken = 0;
    for (std::size_t k = 0; k < scored_.size(); ++k) {
        if (k == 0 || scored_[k].current != scored_[k - 1].current)
            taken = 0;
        if (taken >= options_.ransac.alternativesPerSegment)
            continue;
        pool_.push_back(scored_[k]);
        ++taken;
    }
}

bool GraphScanMatcher::refine(const PolarScan& referenceScan, const PolarScan& currentScan,
                              const Hypothesis& h, Refined& out) {
    CPose2D pose = h.pose;
    // Least squares on the lines of every agreeing pair (the paper's 2-3 segments and more).
    lines_.clear();
    for (const SegmentMatch& m : h.consensus) {
        const SegmentNode& cn = current_.node(m.current);
        const SegmentNode& rn = reference_.node(m.reference);
        lines_.push_back(
            {cn.midpoint, cn.direction, rn.midpoint, rn.direction, std::min(cn.length, rn.length)});
    }
    const TransformEstimate fit = rigidTransformFromLines(lines_);
    const bool alongLine = fit.valid && fit.conditioning < options_.alongLineConditioning;
    // A pose from the points (HoughPoseSearch) on parallel lines has its position along them
    // from the points: the lines' fit does not know it, and the search along them starts
    // from there, not from where another hypothesis on the same lines went.
    const bool keepPosition = alongLine && h.positionFromPoints;
    if (fit.valid && fit.conditioning > 0.01 && !keepPosition)
        pose = fit.pose;
    if (alongLine && !keepPosition) {
        // A hypothesis on the same lines as one already searched along them (same rotation,
        // same position across them) would end where that one did.
        const CPose2D base = fit.valid ? fit.pose : pose;
        for (const Refined& r : refined_) {
            if (!r.searchedAlongLine)
                continue;
            const double dx = r.lineBase.x() - base.x(), dy = r.lineBase.y() - base.y();
            const double across = std::abs(-dy * r.lineDirection.x + dx * r.lineDirection.y);
            if (std::abs(mrpt::math::wrapToPi(r.lineBase.phi() - base.phi())) <
                    options_.ransac.distinctRotation &&
                across < options_.ransac.distinctTranslation &&
                std::abs(fit.weakDirection.x * r.lineDirection.x +
                         fit.weakDirection.y * r.lineDirection.y) > 0.95)
                return false;
        }
        out.lineBase = base;
        out.lineDirection = fit.weakDirection;
    }

    // Point-to-line ICP on the agreeing segments; a second round picks up segments that
    // agree only once the pose is refined.
    for (int round = 0; round < 2; ++round) {
        RansacMatcher::consensus(current_, reference_, pose, options_.ransac, &consensus_);
        if (consensus_.empty())
            break;
        out.icp = icp_.refine(currentScan, current_, reference_, consensus_, pose, options_.icp);
        pose = out.icp.pose;
    }
    // Matched lines all (nearly) parallel: the position along them is still open.
    if (alongLine && !consensus_.empty()) {
        AlongLineSearchOptions search = options_.alongLine;
        double longest = 0;
        for (const SegmentMatch& m : consensus_)
            longest = std::max(longest, current_.node(m.current).length);
        search.range = std::min(search.range, longest);
        pose = alongLine_.search(referenceScan, currentScan, pose, fit.weakDirection, search,
                                 options_.score);
        out.searchedAlongLine = !keepPosition;  // a search from the lines' own start
    }
    out.pose = pose;
    // Screening score: forward only, sparse, tolerant to the coarse pose's residual error.
    AlignmentScoreOptions screen = options_.score;
    screen.stride = options_.screenStride;
    screen.inlierDistance = 2 * options_.score.inlierDistance;
    const AlignmentScore a = scoreAlignment(referenceScan, currentScan, pose, screen);
    out.screenValue = double(a.inliers) - double(a.violations);
    return true;
}

void GraphScanMatcher::polish(const PolarScan& referenceScan, const PolarScan& currentScan,
                              Refined& out) {
    if (options_.scanRefinement) {
        out.icp = icp_.refineOnScan(referenceScan, currentScan, out.pose, options_.scanIcp,
                                    options_.score.searchBeams + 1);
        out.pose = out.icp.pose;
    }
    // Value: each inlier counts 1 - (d / inlierDistance)^2 (a tighter fit scores higher,
    // which separates poses a few centimetres apart that all have the same inliers), each
    // free-space violation -1.
    const double inv2 = 1.0 / (options_.score.inlierDistance * options_.score.inlierDistance);
    const auto value = [&](const AlignmentScore& a) {
        return double(a.inliers) - a.inlierSquaredError * inv2 - double(a.violations);
    };
    out.score = scoreAlignment(referenceScan, currentScan, out.pose, options_.score);
    out.value = value(out.score);
    if (options_.symmetricScore) {
        // The reference scan seen from the current one: a pose that explains the current
        // points but puts reference points in the current scan's free space is wrong too.
        out.reverseScore = scoreAlignment(currentScan, referenceScan, -out.pose, options_.score);
        out.value += value(out.reverseScore);
    }
    out.polished = true;
}

void GraphScanMatcher::addRefined(const PolarScan& referenceScan, const PolarScan& currentScan,
                                  const Hypothesis& h, std::size_t index) {
    Refined refined;
    refined.hypothesis = index;
    if (!refine(referenceScan, currentScan, h, refined))
        return;
    // Converged onto an earlier (better supported) hypothesis's pose: the same solution.
    for (const Refined& r : refined_)
        if (!posesDistinct(r.pose, refined.pose, options_.ransac.distinctTranslation,
                           options_.ransac.distinctRotation))
            return;
    refined_.push_back(refined);
}

void GraphScanMatcher::polishCandidates(const PolarScan& referenceScan,
                                        const PolarScan& currentScan) {
    // The full refinement (scan ICP, symmetric scoring) for the best screened poses only:
    // the leader, and any other within polishRatio of it (a possible better pose or a
    // look-alike that makes the match ambiguous). The rest cannot win and are dropped.
    double leader = -std::numeric_limits<double>::infinity();
    for (const Refined& r : refined_)
        if (!r.polished)
            leader = std::max(leader, r.screenValue);
    std::size_t kept = 0;
    for (Refined& r : refined_) {
        if (!r.polished) {
            if (r.screenValue < leader - (1 - options_.polishRatio) * std::abs(leader))
                continue;
            polish(referenceScan, currentScan, r);
        }
        // After polishing two poses may coincide: keep the first (better supported).
        bool duplicate = false;
        for (std::size_t k = 0; k < kept; ++k)
            duplicate = duplicate || !posesDistinct(refined_[k].pose, r.pose,
                                                    options_.ransac.distinctTranslation,
                                                    options_.ransac.distinctRotation);
        if (!duplicate)
            refined_[kept++] = r;
    }
    refined_.resize(kept);
}

void GraphScanMatcher::decide() {
    MatchResult& r = result_;
    if (refined_.empty())
        return;
    // Best explained first; equal evidence: the tighter fit.
    std::stable_sort(refined_.begin(), refined_.end(), [](const Refined& a, const Refined& b) {
        if (a.value != b.value)
            return a.value > b.value;
        return a.score.inlierRms() < b.score.inlierRms();
    });
    // Distinct solutions only (a polished or locally improved pose may reach another's).
    std::size_t kept = 0;
    for (std::size_t k = 0; k < refined_.size(); ++k) {
        bool duplicate = false;
        for (std::size_t j = 0; j < kept && !duplicate; ++j)
            duplicate = !posesDistinct(refined_[j].pose, refined_[k].pose,
                                       options_.ransac.distinctTranslation,
                                       options_.ransac.distinctRotation);
        if (!duplicate)
            refined_[kept++] = refined_[k];
    }
    refined_.resize(kept);
    const Refined& best = refined_.front();
    r.pose = best.pose;
    r.covariance = best.icp.covariance;
    r.residualRms = best.icp.residualRms;
    r.score = best.score;
    r.reverseScore = best.reverseScore;
    // Evidence in both directions when scored symmetrically: counts add up.
    AlignmentScore evidence = best.score;
    if (options_.symmetricScore) {
        evidence.inliers += best.reverseScore.inliers;
        evidence.violations += best.reverseScore.violations;
        evidence.unverifiable += best.reverseScore.unverifiable;
        evidence.outOfView += best.reverseScore.outOfView;
        evidence.inlierSquaredError += best.reverseScore.inlierSquaredError;
    }
    const double scored = double(evidence.verified() + evidence.unverifiable);
    r.quality = scored > 0 ? evidence.inlierFraction() * double(evidence.inliers) / scored : 0.0;
    RansacMatcher::consensus(current_, reference_, best.pose, options_.ransac, &consensus_);
    r.matches.clear();
    for (const SegmentMatch& m : consensus_)
        r.matches.push_back(
            {current_.node(m.current).segment, reference_.node(m.reference).segment});

    // refined_ holds pairwise distinct poses: the runner-up is the best alternative.
    double lead = std::numeric_limits<double>::infinity();
    r.alternative.reset();
    r.ambiguity = 0;
    if (refined_.size() > 1) {
        const Refined& alt = refined_[1];
        r.alternative = alt.pose;
        r.ambiguity = best.value > 0 ? std::max(0.0, alt.value) / best.value : 1.0;
        lead = best.value - alt.value;
    }

    // Overlap: a share of all points, or most of those the other sensor could have seen.
    const double visible = scored - double(evidence.outOfView);
    const bool overlapping = double(evidence.inliers) >= options_.minInlierRatio * scored ||
                             (options_.minVisibleInlierRatio > 0 &&
                              double(evidence.inliers) >= options_.minVisibleInlierRatio * visible);
    if (best.score.inliers < minInliers_ || !overlapping ||
        evidence.inlierFraction() < options_.minInlierFraction) {
        r.status = MatchStatus::PoorFit;
    } else if (best.icp.pointsUsed < 3 ||
               best.icp.worstTranslationStd > options_.maxTranslationStd) {
        r.status = MatchStatus::Degenerate;
    } else if (lead < options_.ambiguityMargin * scored) {
        r.status = MatchStatus::Ambiguous;
    } else {
        r.status = MatchStatus::Matched;
    }
}

void GraphScanMatcher::searchWeakDirection(const PolarScan& referenceScan,
                                           const PolarScan& currentScan) {
    if (refined_.empty() || options_.weakDirectionRange <= 0)
        return;
    const Refined& best = refined_.front();
    if (weakDirectionSearched_ && !posesDistinct(*weakDirectionSearched_, best.pose, 1e-3, 1e-4))
        return;  // the fallback kept the graph's best: searched already
    weakDirectionSearched_ = best.pose;
    // Eigen-decomposition of the translation covariance [a b; b c]: worst and best variances
    // and the worst direction.
    const mrpt::math::CMatrixDouble33& cov = best.icp.covariance;
    const double a = cov(0, 0), b = cov(0, 1), c = cov(1, 1);
    const double spread = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    const double worst = 0.5 * (a + c) + spread, across = 0.5 * (a + c) - spread;
    const double elongation = options_.weakDirectionElongation;
    if (worst < elongation * elongation * std::max(across, 0.0))
        return;  // determined about equally well in every direction: ICP's minimum stands
    const double angle = 0.5 * std::atan2(2 * b, a - c);
    AlongLineSearchOptions search = options_.alongLine;
    search.range = options_.weakDirectionRange;
    const CPose2D moved =
        alongLine_.search(referenceScan, currentScan, best.pose, {std::cos(angle), std::sin(angle)},
                          search, options_.score);
    if (!posesDistinct(moved, best.pose, 1e-3, 1e-4))
        return;
    // The moved pose competes with the others on the full score (decide() keeps the better
    // of two coinciding poses, and weighs distinct ones for ambiguity).
    Refined r;
    r.pose = moved;
    r.icp = best.icp;  // kept if scan-mode refinement is off
    r.hypothesis = best.hypothesis;
    polish(referenceScan, currentScan, r);
    refined_.push_back(r);
    decide();
}

const MatchResult& GraphScanMatcher::match(const PolarScan& referenceScan,
                                           const features::ScanFeatures& referenceFeatures,
                                           const PolarScan& currentScan,
                                           const features::ScanFeatures& currentFeatures,
                                           const std::optional<CPose2D>& guess) {
    MatchResult& r = result_;
    r.status = MatchStatus::TooFewFeatures;
    r.pose = CPose2D();
    r.covariance.setZero();
    r.quality = r.residualRms = r.ambiguity = 0;
    r.score = {};
    r.reverseScore = {};
    r.alternative.reset();
    r.matches.clear();
    r.candidates = r.hypotheses = 0;
    r.spgmIterations = 0;
    r.usedFallback = false;
    r.retriedWithoutGuess = false;
    r.secondsGraph = r.secondsRansac = r.secondsRefine = r.secondsFallback = 0;
    refined_.clear();
    weakDirectionSearched_.reset();
    auto t0 = threadCpuSeconds();
    // As many inliers as cover the bearing min_inliers cover at the stated beam spacing.
    const double step = std::abs(currentScan.bearingStep());
    minInliers_ = options_.minInliers;
    if (options_.minInliersBearingStep > 0 && step > 0) {
        minInliers_ = std::max<std::size_t>(
            1, std::size_t(std::lround(double(options_.minInliers) *
                                       options_.minInliersBearingStep / step)));
    }

    current_.build(currentFeatures.segments, options_.minSegmentLength, options_.maxSegments);
    reference_.build(referenceFeatures.segments, options_.minSegmentLength, options_.maxSegments);
    r.currentNodes = current_.size();
    r.referenceNodes = reference_.size();
    if (current_.empty() || reference_.empty())
        return r;

    // SPGM rows: the smaller graph, so that "every row matched once" can hold.
    swapped_ = current_.size() > reference_.size();
    buildCandidates(guess);
    r.candidates = candidates_.size();
    if (options_.scanRefinement)
        icp_.prepareReference(referenceScan, options_.score.maxJoinDistance);

    if (current_.size() >= 2 && reference_.size() >= 2 && candidates_.size() >= 2) {
        r.status = MatchStatus::NoConsensus;
        const AttributedGraph& rows = swapped_ ? reference_ : current_;
        const AttributedGraph& cols = swapped_ ? current_ : reference_;
        similarity_.build(rows, cols, candidates_, options_.similarity);
        const std::vector<double>& p =
            spgm_.solve(similarity_, candidates_, rows.size(), cols.size(), options_.spgm);
        r.spgmIterations = spgm_.iterations();
        for (std::size_t k = 0; k < p.size(); ++k)
            scored_[k].probability = p[k];
        greedy_.solve(candidates_, p, rows.size(), cols.size());
        const double t1 = threadCpuSeconds();
        r.secondsGraph = t1 - t0;

        buildPool();
        const std::vector<Hypothesis>& hyps =
            ransac_.run(current_, reference_, pool_, options_.ransac, guess);
        r.hypotheses = ransac_.evaluated();
        const double t2 = threadCpuSeconds();
        r.secondsRansac = t2 - t1;
        for (std::size_t h = 0; h < hyps.size() && h < options_.refineTop; ++h)
            addRefined(referenceScan, currentScan, hyps[h], h);
        polishCandidates(referenceScan, currentScan);
        decide();
        searchWeakDirection(referenceScan, currentScan);
        t0 = threadCpuSeconds();
        r.secondsRefine = t0 - t2;
    }

    // Nothing reliable from the graph: rotations from segment pairs, translations from all
    // points (HoughPoseSearch), refined and judged the same way, together with the graph's.
    if (options_.houghFallback && r.status != MatchStatus::Matched &&
        r.status != MatchStatus::Ambiguous && !scored_.empty()) {
        r.usedFallback = true;
        const std::vector<PoseCandidate>& poses = hough_.search(
            referenceScan, currentScan, current_, reference_, scored_, options_.hough);
        for (std::size_t k = 0; k < poses.size() && k < options_.houghRefineTop; ++k) {
            if (guess && posesDistinct(poses[k].pose, *guess, options_.guessTranslationWindow,
                                       options_.guessRotationWindow))
                continue;
            fallback_.pose = poses[k].pose;
            fallback_.positionFromPoints = true;
            RansacMatcher::consensus(current_, reference_, fallback_.pose, options_.ransac,
                                     &fallback_.consensus);
            addRefined(referenceScan, currentScan, fallback_, options_.refineTop + k);
        }
        r.hypotheses += poses.size();
        polishCandidates(referenceScan, currentScan);
        decide();
        searchWeakDirection(referenceScan, currentScan);
        r.secondsFallback = threadCpuSeconds() - t0;
    }
    // A guess that pruned the truth away (odometry drifted beyond the windows): once more
    // without it, keeping the result only if that one is reliable.
    if (guess && options_.guessFreeRetry && !r.reliable()) {
        const MatchResult guided = r;
        match(referenceScan, referenceFeatures, currentScan, currentFeatures, std::nullopt);
        if (!r.reliable())
            r = guided;
        r.retriedWithoutGuess = true;
    }
    return r;
}

void GraphMatcherOptions::declare(config::OptionsSchema& s) {
    // Attributed graph (paper sec. 2.2) and candidate assignments.
    s.real("min_segment_length", minSegmentLength, "m", "shorter segments are not graph nodes")
        .atLeast(0);
    // The similarity matrix grows with the fourth power of this.
    s.integer("max_segments", maxSegments, "",
              "per scan, the longest ones (bounds the (n n')^2 similarity cost)")
        .within(2, 64);
    s.real("min_length_ratio", minLengthRatio, "",
           "no guess: shorter/longer length of a candidate pair (occlusion!)")
        .within(0, 1);
    s.real("guess_translation_window", guessTranslationWindow, "m",
           "with a guess: predicted position error accepted")
        .atLeast(0);
    s.angle("guess_rotation_window", guessRotationWindow,
            "with a guess: predicted direction error accepted")
        .within(0, 180);
    s.flag("guess_free_retry", guessFreeRetry, "guided match failed: retry without the guess");
    // Steps 3-6.
    s.group("similarity_", similarity);
    s.group("spgm_", spgm);
    s.group("ransac_", ransac);
    declareRefinement(s);
    declareDecision(s);
}

void GraphMatcherOptions::declareRefinement(config::OptionsSchema& s) {
    s.integer("refine_top", refineTop, "", "RANSAC hypotheses refined").within(1, 1000);
    s.integer("screen_stride", screenStride, "", "screening score on every n-th point ...")
        .within(1, 1000);
    s.real("polish_ratio", polishRatio, "",
           "... only those within this ratio of the best are polished")
        .within(0, 1);
    s.group("icp_", icp);
    s.real("along_line_conditioning", alongLineConditioning, "",
           "consensus lines this near parallel (eigenvalue ratio): search along them")
        .within(0, 1);
    s.group("along_line_", alongLine);
    s.real("weak_direction_range", weakDirectionRange, "m",
           "search the best pose's weakest direction this far (0: off) ...")
        .atLeast(0);
    s.real("weak_direction_elongation", weakDirectionElongation, "",
           "... when its std there is at least this many times the std across")
        .atLeast(0);
    s.flag("scan_refinement", scanRefinement, "polish with scan-mode ICP on all points");
    s.group("scan_icp_", scanIcp);
    s.flag("symmetric_score", symmetricScore, "score both ways (current on reference and back)");
    s.group("score_", score);
    s.flag("hough_fallback", houghFallback,
           "search with HoughPoseSearch when the graph finds nothing reliable");
    s.integer("hough_refine_top", houghRefineTop, "", "Hough poses refined").within(0, 1000);
    s.group("hough_", hough);
}

void GraphMatcherOptions::declareDecision(config::OptionsSchema& s) {
    s.integer("min_inliers", minInliers, "",
              "current points on the reference surface, for a laser with ...")
        .within(0, 1000000);
    s.angle("min_inliers_bearing_step", minInliersBearingStep,
            "... this between beams (other lasers: as many as cover the same bearing; 0: as "
            "is)")
        .atLeast(0)
        .atMost(180);
    s.real("min_inlier_ratio", minInlierRatio, "", "of the scored points (both ways) ...")
        .within(0, 1);
    s.real("min_visible_inlier_ratio", minVisibleInlierRatio, "",
           "... or of those inside the other sensor's view, e.g. 0.7 (0: off)")
        .within(0, 1);
    s.real("min_inlier_fraction", minInlierFraction, "",
           "inliers / (inliers + free-space violations)")
        .within(0, 1);
    s.real("max_translation_std", maxTranslationStd, "m", "worst direction of the refined pose")
        .above(0);
    s.real("ambiguity_margin", ambiguityMargin, "",
           "best must beat any distinct pose by this fraction of the points")
        .within(0, 1);
}

}  // namespace toposlam::matching
