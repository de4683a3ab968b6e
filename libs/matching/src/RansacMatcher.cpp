#include <mrpt/math/wrap2pi.h>
#include <toposlam/matching/RansacMatcher.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

void RansacOptions::declare(config::OptionsSchema& s) {
    s.integer("max_hypotheses", maxHypotheses, "",
              "segment-pair samples tried, most probable first")
        .within(0, 100000);
    s.integer("max_single_hypotheses", maxSingleHypotheses, "",
              "single-segment samples (x3 anchors) after the pairs")
        .within(0, 100000);
    s.integer("alternatives_per_segment", alternativesPerSegment, "",
              "reference candidates per observed segment from P")
        .within(1, 100);
    s.real("probability_floor", probabilityFloor, "",
           "added to P in the sample weights (look-alikes get tried)")
        .atLeast(0);
    s.angle("min_sample_angle", minSampleAngle, "sampled segments at least this far from parallel")
        .within(0, 90);
    s.angle("sample_angle_tolerance", sampleAngleTolerance,
            "relative angles of a sample must agree within it")
        .within(0, 180);
    s.angle("consensus_angle", consensusAngle, "direction agreement for the consensus")
        .above(0)
        .atMost(180);
    s.angle("short_segment_angle_slack", shortSegmentAngleSlack,
            "the angle tolerances grow by this / the shorter segment's length", "deg x m")
        .atLeast(0);
    s.real("consensus_distance", consensusDistance, "m", "end points to the matched line").above(0);
    s.real("overlap_margin", overlapMargin, "m", "gap allowed along the line").atLeast(0);
    s.integer("max_kept", maxKept, "", "distinct hypotheses kept").within(1, 1000);
    s.real("distinct_translation", distinctTranslation, "m",
           "poses farther apart are different solutions")
        .atLeast(0);
    s.angle("distinct_rotation", distinctRotation, "... or turned further apart").atLeast(0);
}

bool posesDistinct(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double translation,
                   double rotation) {
    return std::hypot(a.x() - b.x(), a.y() - b.y()) > translation ||
           std::abs(mrpt::math::wrapToPi(a.phi() - b.phi())) > rotation;
}

double RansacMatcher::consensus(const AttributedGraph& current, const AttributedGraph& reference,
                                const mrpt::poses::CPose2D& pose, const RansacOptions& options,
                                std::vector<SegmentMatch>* out) {
    if (out)
        out->clear();
    const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
    double support = 0;
    for (std::uint32_t i = 0; i < current.size(); ++i) {
        const SegmentNode& n = current.node(i);
        const double heading = n.heading + pose.phi();
        const double ax = pose.x() + c * n.start.x - s * n.start.y;
        const double ay = pose.y() + s * n.start.x + c * n.start.y;
        const double bx = pose.x() + c * n.end.x - s * n.end.y;
        const double by = pose.y() + s * n.end.x + c * n.end.y;
        bool agrees = false;
        for (std::uint32_t a = 0; a < reference.size(); ++a) {
            const SegmentNode& r = reference.node(a);
            if (std::abs(mrpt::math::wrapToPi(heading - r.heading)) >
                options.consensusAngle +
                    options.shortSegmentAngleSlack / std::min(n.length, r.length))
                continue;
            const double da = r.normal.x * ax + r.normal.y * ay - r.offset;
            const double db = r.normal.x * bx + r.normal.y * by - r.offset;
            if (std::abs(da) > options.consensusDistance ||
                std::abs(db) > options.consensusDistance)
                continue;
            // Overlap along the reference direction: [ta, tb] against [0, length].
            const double ta = (ax - r.start.x) * r.direction.x + (ay - r.start.y) * r.direction.y;
            const double tb = (bx - r.start.x) * r.direction.x + (by - r.start.y) * r.direction.y;
            const double lo = std::min(ta, tb), hi = std::max(ta, tb);
            if (hi < -options.overlapMargin || lo > r.length + options.overlapMargin)
                continue;
            agrees = true;
            if (out)
                out->push_back({i, a});
            else
                break;
        }
        if (agrees)
            support += n.length;
    }
    return support;
}

void RansacMatcher::offer(const AttributedGraph& current, const AttributedGraph& reference,
                          const mrpt::poses::CPose2D& pose, const RansacOptions& options) {
    ++evaluated_;
    const double support = consensus(current, reference, pose, options);
    if (support <= 0)
        return;
    // Replace a similar kept hypothesis if this one is better, else insert if it ranks.
    const auto bySupport = [](const Hypothesis& a, const Hypothesis& b) {
        return a.support > b.support;
    };
    for (Hypothesis& h : kept_) {
        if (!posesDistinct(h.pose, pose, options.distinctTranslation, options.distinctRotation)) {
            if (support > h.support) {
                h.pose = pose;
                h.support = support;
                std::stable_sort(kept_.begin(), kept_.end(), bySupport);
            }
            return;
        }
    }
    if (kept_.size() < options.maxKept) {
        kept_.push_back({pose, support, {}});
    } else if (support > kept_.back().support) {
        kept_.back().pose = pose;
        kept_.back().support = support;
    } else {
        return;
    }
    std::stable_sort(kept_.begin(), kept_.end(), bySupport);
}

const std::vector<Hypothesis>& RansacMatcher::run(
    const AttributedGraph& current, const AttributedGraph& reference,
    const std::vector<ScoredAssignment>& assignments, const RansacOptions& options,
    const std::optional<mrpt::poses::CPose2D>& guess) {
    kept_.clear();
    evaluated_ = 0;
    buildPool(assignments);
    offerPairs(current, reference, options);
    offerSingles(current, reference, options);
    if (guess)
        offer(current, reference, *guess, options);
    for (Hypothesis& h : kept_)
        consensus(current, reference, h.pose, options, &h.consensus);
    return kept_;
}

void RansacMatcher::buildPool(const std::vector<ScoredAssignment>& assignments) {
    // Unique (current, reference) pairs, best probability first.
    pool_ = assignments;
    std::sort(pool_.begin(), pool_.end(), [](const ScoredAssignment& a, const ScoredAssignment& b) {
        if (a.current != b.current)
            return a.current < b.current;
        if (a.reference != b.reference)
            return a.reference < b.reference;
        return a.probability > b.probability;
    });
    pool_.erase(std::unique(pool_.begin(), pool_.end(),
                            [](const ScoredAssignment& a, const ScoredAssignment& b) {
                                return a.current == b.current && a.reference == b.reference;
                            }),
                pool_.end());
}

void RansacMatcher::offerPairs(const AttributedGraph& current, const AttributedGraph& reference,
                               const RansacOptions& options) {
    // Samples: pairs of pool entries with distinct segments on both sides, non-parallel
    // observed segments and matching relative angles.
    samples_.clear();
    const double sinMin = std::sin(options.minSampleAngle);
    for (std::uint32_t u = 0; u < pool_.size(); ++u) {
        const ScoredAssignment& A = pool_[u];
        const SegmentNode& ci = current.node(A.current);
        const SegmentNode& ra = reference.node(A.reference);
        const double wu =
            (A.probability + options.probabilityFloor) * std::min(ci.length, ra.length);
        for (std::uint32_t v = u + 1; v < pool_.size(); ++v) {
            const ScoredAssignment& B = pool_[v];
            if (B.current == A.current || B.reference == A.reference)
                continue;
            const double angleCur = current.edge(A.current, B.current)[AttributedGraph::Angle];
            if (std::abs(std::sin(angleCur)) < sinMin)
                continue;
            const double angleRef =
                reference.edge(A.reference, B.reference)[AttributedGraph::Angle];
            const SegmentNode& cj = current.node(B.current);
            const SegmentNode& rb = reference.node(B.reference);
            const double shortest = std::min({ci.length, ra.length, cj.length, rb.length});
            if (std::abs(mrpt::math::wrapToPi(angleCur - angleRef)) >
                options.sampleAngleTolerance + options.shortSegmentAngleSlack / shortest)
                continue;
            const double wv =
                (B.probability + options.probabilityFloor) * std::min(cj.length, rb.length);
            samples_.push_back({u, v, wu * wv});
        }
    }
    std::sort(samples_.begin(), samples_.end(), [&](const Sample& a, const Sample& b) {
        if (a.weight != b.weight)
            return a.weight > b.weight;
        return a.u != b.u ? a.u < b.u : a.v < b.v;
    });
    if (samples_.size() > options.maxHypotheses)
        samples_.resize(options.maxHypotheses);

    for (const Sample& sm : samples_) {
        lines_.clear();
        for (std::uint32_t e : {sm.u, sm.v}) {
            const SegmentNode& cn = current.node(pool_[e].current);
            const SegmentNode& rn = reference.node(pool_[e].reference);
            lines_.push_back({cn.midpoint, cn.direction, rn.midpoint, rn.direction,
                              std::min(cn.length, rn.length)});
        }
        const TransformEstimate t = rigidTransformFromLines(lines_);
        if (!t.valid)
            continue;
        offer(current, reference, t.pose, options);
    }
}

void RansacMatcher::offerSingles(const AttributedGraph& current, const AttributedGraph& reference,
                                 const RansacOptions& options) {
    // Single matches: one segment fixes the rotation and the across-line translation; the
    // along-line one is taken from the midpoints and from either end (one end of a partly
    // occluded wall is usually its true corner). Weaker than pairs, but the only hypotheses
    // where every long segment is parallel (corridors), where clutter the graph does not
    // hold fixes the position.
    singles_.clear();
    for (std::uint32_t u = 0; u < pool_.size(); ++u) {
        const SegmentNode& cn = current.node(pool_[u].current);
        const SegmentNode& rn = reference.node(pool_[u].reference);
        singles_.push_back(
            {u, u,
             (pool_[u].probability + options.probabilityFloor) * std::min(cn.length, rn.length)});
    }
    std::sort(singles_.begin(), singles_.end(), [&](const Sample& a, const Sample& b) {
        if (a.weight != b.weight)
            return a.weight > b.weight;
        return a.u < b.u;
    });
    if (singles_.size() > options.maxSingleHypotheses)
        singles_.resize(options.maxSingleHypotheses);
    for (const Sample& sm : singles_) {
        const SegmentNode& cn = current.node(pool_[sm.u].current);
        const SegmentNode& rn = reference.node(pool_[sm.u].reference);
        const double phi = mrpt::math::wrapToPi(rn.heading - cn.heading);
        const double c = std::cos(phi), s = std::sin(phi);
        const std::pair<const mrpt::math::TPoint2D*, const mrpt::math::TPoint2D*> anchors[] = {
            {&cn.midpoint, &rn.midpoint}, {&cn.start, &rn.start}, {&cn.end, &rn.end}};
        for (const auto& [p, q] : anchors) {
            offer(current, reference,
                  mrpt::poses::CPose2D(q->x - (c * p->x - s * p->y), q->y - (s * p->x + c * p->y),
                                       phi),
                  options);
        }
    }
}

}  // namespace toposlam::matching
