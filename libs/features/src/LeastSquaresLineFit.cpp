#include <toposlam/features/LeastSquaresLineFit.h>

#include <cmath>

namespace toposlam::features {

LineFit fitLeastSquares(const PointSums& s) {
    LineFit fit;
    if (s.n < 2)
        return fit;
    const double mx = s.sx / s.n, my = s.sy / s.n;
    const double a = s.sxx / s.n - mx * mx, b = s.sxy / s.n - mx * my, c = s.syy / s.n - my * my;
    const double mean = 0.5 * (a + c), dev = std::sqrt(sq2(0.5 * (a - c), b));
    const double lambdaMax = mean + dev, lambdaMin = std::max(mean - dev, 0.0);
    if (!(lambdaMax > 0))
        return fit;

    // Eigenvector of the largest eigenvalue (the line's direction), from the better
    // conditioned of the two rows of (C - lambdaMax I); no trigonometry.
    double ux = b, uy = lambdaMax - a;
    const double vx = lambdaMax - c, vy = b;
    if (vx * vx + vy * vy > ux * ux + uy * uy) {
        ux = vx;
        uy = vy;
    }
    double norm = std::sqrt(sq2(ux, uy));
    if (!(norm > 0)) {  // isotropic scatter along an axis: a == lambdaMax, b == 0
        ux = a >= c ? 1 : 0;
        uy = a >= c ? 0 : 1;
        norm = 1;
    }
    const mrpt::math::TPoint2D anchor(s.ox + mx, s.oy + my);
    fit.line = lineThrough({-uy / norm, ux / norm}, anchor, &fit.normal);
    fit.anchor = anchor;
    fit.offsetVarFactor = 1.0 / s.n;
    fit.directionVarFactor = 1.0 / (s.n * lambdaMax);  // 1 / sum of squared spreads along it
    fit.count = static_cast<std::uint32_t>(s.n);
    fit.residualRms = std::sqrt(lambdaMin);
    fit.sums = s;
    fit.ok = true;
    return fit;
}

LineFit fitLeastSquares(const ScanPoints& pts, std::size_t begin, std::size_t end) {
    PointSums s;
    if (end < begin + 1)
        return {};
    s.reset(pts.x(begin), pts.y(begin));
    for (std::size_t k = begin; k <= end; ++k)
        s.add(pts.x(k), pts.y(k));
    return fitLeastSquares(s);
}

}  // namespace toposlam::features
