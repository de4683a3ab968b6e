#include <toposlam/features/LeastSquaresLineFit.h>
#include <toposlam/features/LineFit.h>
#include <toposlam/features/TwoPointLineFit.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

const char* toString(LineFitMethod m) {
    return m == LineFitMethod::TwoPoint ? "two-point" : "least-squares";
}

double PointSums::sumSquaredDistance(const mrpt::math::TPoint2D& nrm, double rho) const {
    const double r = rho - (nrm.x * ox + nrm.y * oy);  // the line in shifted coordinates
    const double s = nrm.x * nrm.x * sxx + 2 * nrm.x * nrm.y * sxy + nrm.y * nrm.y * syy -
                     2 * r * (nrm.x * sx + nrm.y * sy) + n * r * r;
    return std::max(s, 0.0);  // rounding can make a perfect fit slightly negative
}

Line2D lineThrough(mrpt::math::TPoint2D normal, const mrpt::math::TPoint2D& p,
                   mrpt::math::TPoint2D* normalOut) {
    double rho = normal.x * p.x + normal.y * p.y;
    if (rho < 0) {
        rho = -rho;
        normal.x = -normal.x;
        normal.y = -normal.y;
    }
    if (normalOut)
        *normalOut = normal;
    Line2D l;
    l.theta = std::atan2(normal.y, normal.x);
    l.rho = rho;
    return l;
}

LineFit fitLine(LineFitMethod method, const ScanPoints& pts, std::size_t begin, std::size_t end) {
    return method == LineFitMethod::TwoPoint ? fitTwoPoint(pts, begin, end)
                                             : fitLeastSquares(pts, begin, end);
}

}  // namespace toposlam::features
