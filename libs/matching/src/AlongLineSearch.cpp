#include <toposlam/matching/AlongLineSearch.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

void AlongLineSearchOptions::declare(config::OptionsSchema& s) {
    s.real("range", range, "m", "searched each side (at most the longest matched segment)")
        .atLeast(0);
    s.real("bin", bin, "m", "vote bin").above(0);
    s.require([this] { return range / bin <= 1e6; }, "bin",
              "too small for the range (> 10^6 bins)");
    s.real("across_tolerance", acrossTolerance, "m", "points this near a line across vote")
        .above(0);
    s.real("fine_step", fineStep, "m", "scorer check around each peak (+-1 step)").above(0);
    s.integer("peaks", peaks, "", "vote peaks checked with the scorer").within(1, 1000);
    s.integer("stride", stride, "", "every stride-th beam of both scans").within(1, 1000);
}

mrpt::poses::CPose2D AlongLineSearch::search(const PolarScan& reference, const PolarScan& current,
                                             const mrpt::poses::CPose2D& pose,
                                             const mrpt::math::TPoint2D& u,
                                             const AlongLineSearchOptions& options,
                                             const AlignmentScoreOptions& score) {
    const std::size_t stride = std::max<std::size_t>(1, options.stride);
    const double nx = -u.y, ny = u.x;  // across
    const long half = long(std::ceil(options.range / options.bin));
    votes_.assign(std::size_t(2 * half + 1), 0u);

    // Reference points in (along, across) coordinates.
    ref_.clear();
    for (std::size_t i = 0; i < reference.size(); i += stride) {
        if (!reference.valid(i))
            continue;
        const mrpt::math::TPoint2D& q = reference.point(i);
        ref_.push_back({q.x * u.x + q.y * u.y, q.x * nx + q.y * ny});
    }
    std::sort(ref_.begin(), ref_.end(), [](const auto& a, const auto& b) { return a.y < b.y; });

    const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
    for (std::size_t i = 0; i < current.size(); i += stride) {
        if (!current.valid(i))
            continue;
        const mrpt::math::TPoint2D& p = current.point(i);
        const double px = pose.x() + c * p.x - s * p.y, py = pose.y() + s * p.x + c * p.y;
        const double along = px * u.x + py * u.y, across = px * nx + py * ny;
        // Reference points at the same position across u: a range of the sorted list.
        auto it = std::lower_bound(ref_.begin(), ref_.end(), across - options.acrossTolerance,
                                   [](const mrpt::math::TPoint2D& a, double v) { return a.y < v; });
        for (; it != ref_.end() && it->y <= across + options.acrossTolerance; ++it) {
            const long b = std::lround((it->x - along) / options.bin);
            if (b >= -half && b <= half)
                ++votes_[std::size_t(b + half)];
        }
    }
    // Votes summed over 3 bins; the strongest peaks (each suppressing +-0.3 m around it) are
    // checked with the scorer, together with the start: the pose moves only when more points
    // confirm the new offset.
    sums_.assign(votes_.size(), 0u);
    for (long b = -half + 1; b < half; ++b)
        sums_[std::size_t(b + half)] = votes_[std::size_t(b + half - 1)] +
                                       votes_[std::size_t(b + half)] +
                                       votes_[std::size_t(b + half + 1)];
    AlignmentScoreOptions sparse = score;  // every stride-th point is evidence enough here
    sparse.stride = stride;
    const auto value = [&](double off) {
        const mrpt::poses::CPose2D q(pose.x() + off * u.x, pose.y() + off * u.y, pose.phi());
        const AlignmentScore a = scoreAlignment(reference, current, q, sparse);
        return double(a.inliers) - double(a.violations);
    };
    double best = 0, bestValue = value(0.0);
    const long suppress = long(std::ceil(0.3 / options.bin));
    for (std::size_t peak = 0; peak < options.peaks; ++peak) {
        const auto it = std::max_element(sums_.begin(), sums_.end());
        if (*it == 0)
            break;
        const long at = long(it - sums_.begin());
        for (long k = std::max(0L, at - suppress);
             k <= std::min(long(sums_.size()) - 1, at + suppress); ++k)
            sums_[std::size_t(k)] = 0;
        const double centre = double(at - half) * options.bin;
        for (long k = -1; k <= 1; ++k) {
            const double off = centre + double(k) * options.fineStep;
            const double v = value(off);
            if (v > bestValue || (v == bestValue && std::abs(off) < std::abs(best)))
                best = off, bestValue = v;
        }
    }
    return mrpt::poses::CPose2D(pose.x() + best * u.x, pose.y() + best * u.y, pose.phi());
}

}  // namespace toposlam::matching
