#include <mrpt/config/CConfigFileBase.h>
#include <toposlam/matching/GraphScanMatcher.h>

#include <algorithm>
#include <cmath>

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
                if (std::abs(wrapAngle(cn.heading + guess->phi() - rn.heading)) >
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
    if (fit.valid && fit.conditioning > 0.01)
        pose = fit.pose;
    const bool alongLine = fit.valid && fit.conditioning < options_.alongLineConditioning;
    if (alongLine) {
        // A hypothesis on the same lines as one already searched along them (same rotation,
        // same position across them) would end where that one did.
        const CPose2D base = fit.valid ? fit.pose : pose;
        for (const Refined& r : refined_) {
            if (!r.searchedAlongLine)
                continue;
            const double dx = r.lineBase.x() - base.x(), dy = r.lineBase.y() - base.y();
            const double across = std::abs(-dy * r.lineDirection.x + dx * r.lineDirection.y);
            if (std::abs(wrapAngle(r.lineBase.phi() - base.phi())) <
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
        pose = searchAlongLine(referenceScan, currentScan, pose, fit.weakDirection, search,
                               options_.score);
        out.searchedAlongLine = true;
    }
    if (options_.scanRefinement && !consensus_.empty()) {
        out.icp = icp_.refineOnScan(referenceScan, currentScan, pose, options_.scanIcp,
                                    options_.score.searchBeams + 1);
        pose = out.icp.pose;
    }
    out.pose = pose;
    out.score = scoreAlignment(referenceScan, currentScan, pose, options_.score);
    out.value = double(out.score.inliers) - double(out.score.violations);
    return true;
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
    r.alternative.reset();
    r.matches.clear();
    r.candidates = r.hypotheses = 0;
    r.spgmIterations = 0;

    current_.build(currentFeatures.segments, options_.minSegmentLength, options_.maxSegments);
    reference_.build(referenceFeatures.segments, options_.minSegmentLength, options_.maxSegments);
    r.currentNodes = current_.size();
    r.referenceNodes = reference_.size();
    if (current_.size() < 2 || reference_.size() < 2)
        return r;

    // SPGM rows: the smaller graph, so that "every row matched once" can hold.
    swapped_ = current_.size() > reference_.size();
    buildCandidates(guess);
    r.candidates = candidates_.size();
    r.status = MatchStatus::NoConsensus;
    if (candidates_.size() < 2)
        return r;

    const AttributedGraph& rows = swapped_ ? reference_ : current_;
    const AttributedGraph& cols = swapped_ ? current_ : reference_;
    similarity_.build(rows, cols, candidates_, options_.similarity);
    const std::vector<double>& p =
        spgm_.solve(similarity_, candidates_, rows.size(), cols.size(), options_.spgm);
    r.spgmIterations = spgm_.iterations();
    for (std::size_t k = 0; k < p.size(); ++k)
        scored_[k].probability = p[k];
    greedy_.solve(candidates_, p, rows.size(), cols.size());

    buildPool();
    const std::vector<Hypothesis>& hyps =
        ransac_.run(current_, reference_, pool_, options_.ransac, guess);
    r.hypotheses = ransac_.evaluated();
    if (hyps.empty())
        return r;

    if (options_.scanRefinement)
        icp_.prepareReference(referenceScan, options_.score.maxJoinDistance);
    refined_.clear();
    for (std::size_t h = 0; h < hyps.size() && h < options_.refineTop; ++h) {
        Refined refined;
        refined.hypothesis = h;
        if (!refine(referenceScan, currentScan, hyps[h], refined))
            continue;
        // Converged onto an earlier (better supported) hypothesis's pose: the same solution.
        bool duplicate = false;
        for (const Refined& r : refined_)
            duplicate = duplicate ||
                        !posesDistinct(r.pose, refined.pose, options_.ransac.distinctTranslation,
                                       options_.ransac.distinctRotation);
        if (!duplicate)
            refined_.push_back(refined);
    }
    // Best explained first; equal evidence: the tighter fit.
    std::stable_sort(refined_.begin(), refined_.end(), [](const Refined& a, const Refined& b) {
        if (a.value != b.value)
            return a.value > b.value;
        return a.score.inlierRms() < b.score.inlierRms();
    });
    const Refined& best = refined_.front();
    r.pose = best.pose;
    r.covariance = best.icp.covariance;
    r.residualRms = best.icp.residualRms;
    r.score = best.score;
    const std::size_t scored = best.score.inliers + best.score.violations + best.score.unverifiable;
    r.quality = scored > 0
                    ? best.score.inlierFraction() * double(best.score.inliers) / double(scored)
                    : 0.0;
    RansacMatcher::consensus(current_, reference_, best.pose, options_.ransac, &consensus_);
    for (const SegmentMatch& m : consensus_)
        r.matches.push_back(
            {current_.node(m.current).segment, reference_.node(m.reference).segment});

    for (std::size_t k = 1; k < refined_.size(); ++k) {
        if (posesDistinct(refined_[k].pose, best.pose, options_.ransac.distinctTranslation,
                          options_.ransac.distinctRotation)) {
            r.alternative = refined_[k].pose;
            r.ambiguity = best.value > 0 ? std::max(0.0, refined_[k].value) / best.value : 1.0;
            break;
        }
    }

    const double validScored = double(scored);
    if (best.score.inliers < options_.minInliers ||
        double(best.score.inliers) < options_.minInlierRatio * validScored ||
        best.score.inlierFraction() < options_.minInlierFraction) {
        r.status = MatchStatus::PoorFit;
    } else if (best.icp.pointsUsed < 3 ||
               best.icp.worstTranslationStd > options_.maxTranslationStd) {
        r.status = MatchStatus::Degenerate;
    } else if (r.ambiguity >= options_.ambiguityRatio) {
        r.status = MatchStatus::Ambiguous;
    } else {
        r.status = MatchStatus::Matched;
    }
    return r;
}

namespace {
void read(const mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& key,
          double& v) {
    v = c.read_double(s, key, v);
}
void read(const mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& key,
          std::size_t& v) {
    v = static_cast<std::size_t>(c.read_uint64_t(s, key, v));
}
void read(const mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& key,
          int& v) {
    v = c.read_int(s, key, v);
}
}  // namespace

void GraphMatcherOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                             const std::string& s) {
    read(c, s, "minSegmentLength", minSegmentLength);
    read(c, s, "maxSegments", maxSegments);
    read(c, s, "minLengthRatio", minLengthRatio);
    read(c, s, "guessTranslationWindow", guessTranslationWindow);
    read(c, s, "guessRotationWindow", guessRotationWindow);
    read(c, s, "similarity_alpha", similarity.alpha);
    read(c, s, "similarity_maxAngleDifference", similarity.maxAngleDifference);
    read(c, s, "spgm_maxIterations", spgm.maxIterations);
    read(c, s, "spgm_tolerance", spgm.tolerance);
    read(c, s, "spgm_projectionCycles", spgm.projectionCycles);
    read(c, s, "spgm_projectionTolerance", spgm.projectionTolerance);
    read(c, s, "ransac_maxHypotheses", ransac.maxHypotheses);
    read(c, s, "ransac_maxSingleHypotheses", ransac.maxSingleHypotheses);
    read(c, s, "ransac_alternativesPerSegment", ransac.alternativesPerSegment);
    read(c, s, "ransac_probabilityFloor", ransac.probabilityFloor);
    read(c, s, "ransac_minSampleAngle", ransac.minSampleAngle);
    read(c, s, "ransac_sampleAngleTolerance", ransac.sampleAngleTolerance);
    read(c, s, "ransac_consensusAngle", ransac.consensusAngle);
    read(c, s, "ransac_shortSegmentAngleSlack", ransac.shortSegmentAngleSlack);
    read(c, s, "ransac_consensusDistance", ransac.consensusDistance);
    read(c, s, "ransac_overlapMargin", ransac.overlapMargin);
    read(c, s, "ransac_maxKept", ransac.maxKept);
    read(c, s, "ransac_distinctTranslation", ransac.distinctTranslation);
    read(c, s, "ransac_distinctRotation", ransac.distinctRotation);
    read(c, s, "icp_maxIterations", icp.maxIterations);
    read(c, s, "icp_maxDistance", icp.maxDistance);
    read(c, s, "icp_robustScale", icp.robustScale);
    read(c, s, "icp_translationTolerance", icp.translationTolerance);
    read(c, s, "icp_rotationTolerance", icp.rotationTolerance);
    read(c, s, "icp_stride", icp.stride);
    read(c, s, "icp_minNoiseStd", icp.minNoiseStd);
    read(c, s, "icp_minEigenRatio", icp.minEigenRatio);
    read(c, s, "scanIcp_minEigenRatio", scanIcp.minEigenRatio);
    int scan = scanRefinement ? 1 : 0;
    read(c, s, "scanRefinement", scan);
    scanRefinement = scan != 0;
    read(c, s, "scanIcp_maxIterations", scanIcp.maxIterations);
    read(c, s, "scanIcp_maxDistance", scanIcp.maxDistance);
    read(c, s, "scanIcp_robustScale", scanIcp.robustScale);
    read(c, s, "scanIcp_stride", scanIcp.stride);
    read(c, s, "scanIcp_minNoiseStd", scanIcp.minNoiseStd);
    read(c, s, "score_inlierDistance", score.inlierDistance);
    long searchBeams = score.searchBeams;
    searchBeams = c.read_int(s, "score_searchBeams", int(searchBeams));
    score.searchBeams = searchBeams;
    read(c, s, "score_stride", score.stride);
    read(c, s, "score_maxJoinDistance", score.maxJoinDistance);
    read(c, s, "alongLineConditioning", alongLineConditioning);
    read(c, s, "alongLine_range", alongLine.range);
    read(c, s, "alongLine_coarseStep", alongLine.coarseStep);
    read(c, s, "alongLine_fineStep", alongLine.fineStep);
    read(c, s, "alongLine_stride", alongLine.stride);
    read(c, s, "refineTop", refineTop);
    read(c, s, "minInliers", minInliers);
    read(c, s, "minInlierRatio", minInlierRatio);
    read(c, s, "minInlierFraction", minInlierFraction);
    read(c, s, "maxTranslationStd", maxTranslationStd);
    read(c, s, "ambiguityRatio", ambiguityRatio);
}

}  // namespace toposlam::matching
