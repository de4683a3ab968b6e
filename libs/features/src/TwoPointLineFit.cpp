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

    // One pass in three branch-free stretches: the two half sums (for the line) and the sums
    // of all readings (for the residual).
    const double* __restrict xs = pts.xData();
    const double* __restrict ys = pts.yData();
    PointSums all;
    all.reset(xs[begin], ys[begin]);
    const auto accumulate = [&](std::size_t from, std::size_t to, double& sx, double& sy) {
        double sxx = 0, sxy = 0, syy = 0;
        sx = sy = 0;
        for (std::size_t k = from; k < to; ++k) {
            const double x = xs[k] - all.ox, y = ys[k] - all.oy;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            syy += y * y;
        }
        all.n += static_cast<double>(to - from);
        all.sx += sx;
        all.sy += sy;
        all.sxx += sxx;
        all.sxy += sxy;
        all.syy += syy;
    };
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0, xm = 0, ym = 0;
    accumulate(begin, firstHalfEnd, x1, y1);
    accumulate(firstHalfEnd, secondHalfBegin, xm, ym);  // the middle reading of an odd count
    accumulate(secondHalfBegin, end + 1, x2, y2);
    const double h = static_cast<double>(half);
    const double dx = (x2 - x1) / h, dy = (y2 - y1) / h;  // mean of 2nd half - mean of 1st
    const double len = std::sqrt(sq2(dx, dy));
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
    fit.sums = all;
    fit.ok = true;
    return fit;
}

}  // namespace toposlam::features
