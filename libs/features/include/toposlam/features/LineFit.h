#pragma once
// What a line fit returns, whichever method made it, and the running point sums both methods
// share. A fit reports, besides the line, what is needed to propagate point noise into the
// line (and from two lines into their corner): with point noise sigma (m, normal to the line),
//     var(normal offset of the line at `anchor`) = sigma^2 * offsetVarFactor,
//     var(direction of the line, rad)            = sigma^2 * directionVarFactor,
// and the two errors are uncorrelated at `anchor`.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/features/ScanPoints.h>

#include <cstddef>
#include <cstdint>

namespace toposlam::features {

/// a^2 + b^2 (std::hypot guards against overflow and is several times slower).
inline double sq2(double a, double b) {
    return a * a + b * b;
}

/// Running sums of 2D points taken relative to an origin (the first point), so that second
/// moments stay well conditioned far from the sensor.
struct PointSums {
    double ox = 0, oy = 0;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;

    void reset(double originX, double originY) {
        ox = originX;
        oy = originY;
        n = sx = sy = sxx = sxy = syy = 0;
    }
    void add(double x, double y) {
        x -= ox;
        y -= oy;
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
    }
    /// Adds another set of sums (any origin): the sums of the union of both point sets.
    void merge(const PointSums& o) {
        const double dx = o.ox - ox, dy = o.oy - oy;  // o's origin in this one's frame
        sxx += o.sxx + 2 * dx * o.sx + o.n * dx * dx;
        syy += o.syy + 2 * dy * o.sy + o.n * dy * dy;
        sxy += o.sxy + dx * o.sy + dy * o.sx + o.n * dx * dy;
        sx += o.sx + o.n * dx;
        sy += o.sy + o.n * dy;
        n += o.n;
    }
    /// Sum of squared distances (m^2) of the points to the line n.p = rho.
    double sumSquaredDistance(const mrpt::math::TPoint2D& normal, double rho) const;
};
struct LineFit {
    Line2D line;
    mrpt::math::TPoint2D normal{1, 0};  ///< (cos theta, sin theta) of `line`
    mrpt::math::TPoint2D anchor;        ///< m, on the line
    double offsetVarFactor = 0;         ///< 1/count for both methods
    double directionVarFactor = 0;      ///< 1/m^2
    double residualRms = 0;             ///< RMS distance of every supporting point to the line, m
    std::uint32_t count = 0;            ///< supporting points
    bool ok = false;                    ///< false for fewer than 2 distinct points
    PointSums sums;                     ///< of the supporting points (to test unions cheaply)
};

enum class LineFitMethod : std::uint8_t {
    TwoPoint,     ///< corner paper, step 4 (TwoPointLineFit.h)
    LeastSquares  ///< orthogonal least squares (LeastSquaresLineFit.h)
};
const char* toString(LineFitMethod m);

/// The line with unit normal `normal` through point p, in Line2D's form (rho >= 0).
Line2D lineThrough(mrpt::math::TPoint2D normal, const mrpt::math::TPoint2D& p,
                   mrpt::math::TPoint2D* normalOut = nullptr);

/// Fits canonical readings begin..end (inclusive, all valid) with the given method.
LineFit fitLine(LineFitMethod method, const ScanPoints& pts, std::size_t begin, std::size_t end);

}  // namespace toposlam::features
