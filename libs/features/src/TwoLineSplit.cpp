#include <toposlam/features/TwoLineSplit.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::features {

namespace {
/// Least-squares residual sum of squares (m^2) of the points between two prefix sums.
double rssBetween(const PointSums& lo, const PointSums& hi) {
    const double n = hi.n - lo.n;
    const double sx = hi.sx - lo.sx, sy = hi.sy - lo.sy;
    const double cxx = (hi.sxx - lo.sxx) - sx * sx / n;
    const double cyy = (hi.syy - lo.syy) - sy * sy / n;
    const double cxy = (hi.sxy - lo.sxy) - sx * sy / n;
    // Smallest eigenvalue of the scatter matrix.
    return 0.5 * (cxx + cyy - std::sqrt((cxx - cyy) * (cxx - cyy) + 4 * cxy * cxy));
}
}  // namespace

void TwoLineSplit::prepare(const ScanPoints& pts, std::size_t begin, std::size_t end) {
    first_ = begin;
    const std::size_t count = end >= begin ? end - begin + 1 : 0;
    prefix_.resize(count + 1);
    prefix_[0].reset(pts.x(begin), pts.y(begin));
    for (std::size_t i = 0; i < count; ++i) {
        prefix_[i + 1] = prefix_[i];
        prefix_[i + 1].add(pts.x(begin + i), pts.y(begin + i));
    }
}

bool TwoLineSplit::find(std::size_t begin, std::size_t end, std::size_t minPoints,
                        std::size_t& at) const {
    minPoints = std::max<std::size_t>(minPoints, 2);
    if (begin < first_ || end < begin + 2 * minPoints || end + 2 > first_ + prefix_.size())
        return false;
    const std::size_t lo = begin - first_, hi = end - first_ + 1;  // prefix indices
    double best = std::numeric_limits<double>::infinity();
    // Cut at reading j: readings lo..j-1 before it, j+1..hi-1 after it.
    for (std::size_t j = lo + minPoints; j + minPoints < hi; ++j) {
        const double r =
            rssBetween(prefix_[lo], prefix_[j]) + rssBetween(prefix_[j + 1], prefix_[hi]);
        if (r < best) {
            best = r;
            at = first_ + j;
        }
    }
    return std::isfinite(best);
}

double TwoLineSplit::residual(std::size_t begin, std::size_t end) const {
    return std::max(0.0, rssBetween(prefix_[begin - first_], prefix_[end - first_ + 1]));
}

}  // namespace toposlam::features
