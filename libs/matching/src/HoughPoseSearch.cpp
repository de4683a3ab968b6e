#include <mrpt/math/wrap2pi.h>
#include <toposlam/matching/HoughPoseSearch.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

void HoughPoseSearchOptions::declare(config::OptionsSchema& s) {
    s.integer("max_rotations", maxRotations, "", "rotation candidates from segment pairs")
        .within(1, 1000);
    s.angle("rotation_bin", rotationBin, "rotation vote bin").above(0);
    s.real("min_rotation_weight", minRotationWeight, "m", "of segment length behind a rotation")
        .atLeast(0);
    s.real("window", window, "m", "translations searched in [-window, window]^2").above(0);
    s.real("cell", cell, "m", "translation vote cell").above(0);
    s.require([this] { return window / cell <= 5000; }, "cell",
              "too small for the window (more than 10^8 vote cells)");
    s.integer("stride", stride, "", "every stride-th beam of both scans").within(1, 1000);
    s.integer("peaks_per_rotation", peaksPerRotation, "", "translation peaks refined per rotation")
        .within(1, 1000);
    s.real("min_peak_fraction", minPeakFraction, "", "of the voting current points, for a peak")
        .within(0, 1);
}

void HoughPoseSearch::rotationCandidates(const AttributedGraph& currentGraph,
                                         const AttributedGraph& referenceGraph,
                                         const std::vector<ScoredAssignment>& pairs,
                                         const HoughPoseSearchOptions& options) {
    const std::size_t bins =
        std::max<std::size_t>(8, std::size_t(std::lround(2 * M_PI / options.rotationBin)));
    const double width = 2 * M_PI / double(bins);
    binWeight_.assign(bins, 0.0);
    binSin_.assign(bins, 0.0);
    binCos_.assign(bins, 0.0);
    for (const ScoredAssignment& p : pairs) {
        const SegmentNode& c = currentGraph.node(p.current);
        const SegmentNode& r = referenceGraph.node(p.reference);
        const double angle = mrpt::math::wrapToPi(r.heading - c.heading);
        const double w = std::min(c.length, r.length);
        const long b = long(std::floor((angle + M_PI) / width)) % long(bins);
        for (long o = -1; o <= 1; ++o) {  // each vote also counts for the neighbouring bins
            const std::size_t k = std::size_t((b + o + long(bins)) % long(bins));
            binWeight_[k] += w;
            binSin_[k] += w * std::sin(angle);
            binCos_[k] += w * std::cos(angle);
        }
    }
    // Local maxima, strongest first.
    rotations_.clear();
    std::vector<std::pair<double, std::size_t>>& peaks = peaks_;  // (weight, bin)
    peaks.clear();
    for (std::size_t k = 0; k < bins; ++k) {
        const double w = binWeight_[k];
        if (w < options.minRotationWeight)
            continue;
        if (w < binWeight_[(k + 1) % bins] || w <= binWeight_[(k + bins - 1) % bins])
            continue;
        peaks.push_back({w, k});
    }
    std::sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (std::size_t i = 0; i < peaks.size() && i < options.maxRotations; ++i) {
        const std::size_t k = peaks[i].second;
        rotations_.push_back(std::atan2(binSin_[k], binCos_[k]));
    }
}

const std::vector<PoseCandidate>& HoughPoseSearch::search(
    const PolarScan& reference, const PolarScan& current, const AttributedGraph& currentGraph,
    const AttributedGraph& referenceGraph, const std::vector<ScoredAssignment>& pairs,
    const HoughPoseSearchOptions& options) {
    out_.clear();
    rotationCandidates(currentGraph, referenceGraph, pairs, options);
    if (rotations_.empty())
        return out_;
    collectPoints(reference, current, options.stride);
    for (const double phi : rotations_)
        vote(phi, 0.0, 0.0, options.window, options.cell, options.peaksPerRotation,
             options.minPeakFraction);
    std::stable_sort(out_.begin(), out_.end(), [](const PoseCandidate& a, const PoseCandidate& b) {
        return a.votes > b.votes;
    });
    return out_;
}

void HoughPoseSearch::collectPoints(const PolarScan& reference, const PolarScan& current,
                                    std::size_t strideOption) {
    const std::size_t stride = std::max<std::size_t>(1, strideOption);
    ref_.clear();
    cur_.clear();
    for (std::size_t i = 0; i < reference.size(); i += stride)
        if (reference.valid(i))
            ref_.push_back(reference.point(i));
    for (std::size_t i = 0; i < current.size(); i += stride)
        if (current.valid(i))
            cur_.push_back(current.point(i));
}

void HoughPoseSearch::vote(double phi, double cx, double cy, double window, double cell,
                           std::size_t peaks, double minPeakFraction) {
    if (ref_.empty() || cur_.empty())
        return;
    const long side = long(std::ceil(2 * window / cell));
    const double inv = 1.0 / cell;
    votes_.assign(std::size_t(side * side), std::uint16_t(0));
    sums_.assign(std::size_t(side * side), 0u);
    const double minVotes = minPeakFraction * double(cur_.size());
    const double c = std::cos(phi), s = std::sin(phi);
    const double ox = cx - window, oy = cy - window;  // lower-left corner of the grid
    // A cell counts current POINTS, not point pairs: a point votes once per cell however many
    // reference points land there, so dense near-range clutter does not outvote far walls.
    lastVoter_.assign(std::size_t(side * side), 0u);
    std::uint32_t voter = 0;
    for (const mrpt::math::TPoint2D& p : cur_) {
        ++voter;
        const double rx = c * p.x - s * p.y + ox, ry = s * p.x + c * p.y + oy;
        for (const mrpt::math::TPoint2D& q : ref_) {
            const long ix = long(std::floor((q.x - rx) * inv));
            const long iy = long(std::floor((q.y - ry) * inv));
            if (ix < 0 || iy < 0 || ix >= side || iy >= side)
                continue;
            const std::size_t cell = std::size_t(iy * side + ix);
            if (lastVoter_[cell] == voter)
                continue;
            lastVoter_[cell] = voter;
            std::uint16_t& v = votes_[cell];
            if (v < 65535)
                ++v;
        }
    }
    // 3x3 sums, then the strongest peaks with their neighbourhoods suppressed.
    for (long y = 1; y + 1 < side; ++y)
        for (long x = 1; x + 1 < side; ++x) {
            std::uint32_t sum = 0;
            for (long dy = -1; dy <= 1; ++dy)
                for (long dx = -1; dx <= 1; ++dx)
                    sum += votes_[std::size_t((y + dy) * side + x + dx)];
            sums_[std::size_t(y * side + x)] = sum;
        }
    for (std::size_t peak = 0; peak < peaks; ++peak) {
        const auto it = std::max_element(sums_.begin(), sums_.end());
        if (double(*it) < minVotes || *it == 0)
            break;
        const long at = long(it - sums_.begin()), px = at % side, py = at / side;
        // Vote-weighted centre of the 3x3 block.
        double wx = 0, wy = 0, w = 0;
        for (long dy = -1; dy <= 1; ++dy)
            for (long dx = -1; dx <= 1; ++dx) {
                const double v = votes_[std::size_t((py + dy) * side + px + dx)];
                wx += v * double(px + dx), wy += v * double(py + dy), w += v;
            }
        const double tx = (wx / w + 0.5) * cell + ox;
        const double ty = (wy / w + 0.5) * cell + oy;
        out_.push_back({mrpt::poses::CPose2D(tx, ty, phi), double(*it)});
        for (long dy = -3; dy <= 3; ++dy)
            for (long dx = -3; dx <= 3; ++dx) {
                const long x = px + dx, y = py + dy;
                if (x >= 0 && y >= 0 && x < side && y < side)
                    sums_[std::size_t(y * side + x)] = 0;
            }
    }
}

}  // namespace toposlam::matching
