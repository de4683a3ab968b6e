#include <toposlam/features/TwoPointLineFit.h>

#include <cmath>

namespace toposlam::features {

LineFit fitTwoPoint(const ScanPoints& pts, std::size_t begin, std::size_t end) {
    LineFit fit;
    if (end < begin + 1)
        return fit;
    const std::size_t count = end - begin + 1, half = count / 2;
    const std::size_t firstHalfEnd = begin + half;  // exclusive
    const std::size_t secondHalfBegin = end + 1 - half;

    // One pass: the two half sums (for the line) and all sums (for the residual).
    PointSums all;
    all.reset(pts.x(begin), pts.y(begin));
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    for (std::size_t k = begin; k <= end; ++k) {
        all.add(pts.x(k), pts.y(k));
        const double x = pts.x(k) - all.ox, y = pts.y(k) - all.oy;
        if (k < firstHalfEnd) {
            x1 += x;
            y1 += y;
        } else if (k >= secondHalfBegin) {
            x2 += x;
            y2 += y;
        }
    }
    const double h = static_cast<double>(half);
    const double dx = (x2 - x1) / h, dy = (y2 - y1) / h;  // mean of 2nd half - mean of 1st
    const double len = std::hypot(dx, dy);
    if (!(len > 0))
        return fit;

    // Equal halves: the midpoint of the two means is the centroid of the points used.
    const mrpt::math::TPoint2D anchor(all.ox + 0.5 * (x1 + x2) / h, all.oy + 0.5 * (y1 + y2) / h);
    fit.line = lineThrough({-dy / len, dx / len}, anchor, &fit.normal);
    fit.anchor = anchor;
    fit.offsetVarFactor = 1.0 / (2 * h);
    fit.directionVarFactor = (2.0 / h) / (len * len);  // var(mean2 - mean1) / distance^2
    fit.count = static_cast<std::uint32_t>(count);
    fit.residualRms = std::sqrt(all.sumSquaredDistance(fit.normal, fit.line.rho) / all.n);
    fit.ok = true;
    return fit;
}

}  // namespace toposlam::features
