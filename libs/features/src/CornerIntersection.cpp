#include <toposlam/features/CornerIntersection.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

using mrpt::math::TPoint2D;

bool intersectLines(const LineFit& a, const LineFit& b, TPoint2D& out) {
    const double det = a.normal.x * b.normal.y - a.normal.y * b.normal.x;
    if (!(std::abs(det) > 1e-9))
        return false;
    out.x = (a.line.rho * b.normal.y - b.line.rho * a.normal.y) / det;
    out.y = (a.normal.x * b.line.rho - b.normal.x * a.line.rho) / det;
    return true;
}

double pointVariance(const LineFit& f, double sensorSigma) {
    // The residual sum of squares has N - 2 degrees of freedom; the sensor's stated noise
    // counts as 2 more (a conjugate prior): long fits trust their residual (which also sees
    // that range noise shrinks by cos(incidence) normal to an oblique wall), short ones the
    // sensor.
    constexpr double priorDof = 2;
    const double n = f.count, rss = n * f.residualRms * f.residualRms;
    return (rss + priorDof * sensorSigma * sensorSigma) / (std::max(n - 2, 0.0) + priorDof);
}

double angleStd(const LineFit& a, const LineFit& b, double sensorSigma) {
    return std::sqrt(pointVariance(a, sensorSigma) * a.directionVarFactor +
                     pointVariance(b, sensorSigma) * b.directionVarFactor);
}

namespace {
/// Variance of the line's normal offset at point p (on the line).
double offsetVarianceAt(const LineFit& f, const TPoint2D& p, double sensorSigma) {
    const double t = (p.x - f.anchor.x) * -f.normal.y + (p.y - f.anchor.y) * f.normal.x;
    return pointVariance(f, sensorSigma) * (f.offsetVarFactor + t * t * f.directionVarFactor);
}
}  // namespace

bool intersectCorner(const LineFit& before, const LineFit& after, const TPoint2D& farBefore,
                     const TPoint2D& farAfter, double sensorSigma, Corner& out) {
    TPoint2D c;
    if (!intersectLines(before, after, c))
        return false;
    out.position = c;

    // Unit directions of the two walls as they leave the corner.
    TPoint2D u1(-before.normal.y, before.normal.x), u2(-after.normal.y, after.normal.x);
    if ((farBefore.x - c.x) * u1.x + (farBefore.y - c.y) * u1.y < 0)
        u1 = TPoint2D(-u1.x, -u1.y);
    if ((farAfter.x - c.x) * u2.x + (farAfter.y - c.y) * u2.y < 0)
        u2 = TPoint2D(-u2.x, -u2.y);
    const double cross = u1.x * u2.y - u1.y * u2.x, dot = u1.x * u2.x + u1.y * u2.y;
    out.angle = std::atan2(std::abs(cross), dot);
    // Walking the scan counter-clockwise we arrive along -u1 and leave along u2; a left turn
    // (the walls wrap around the sensor) is a concave corner.
    const double turn = -u1.x * u2.y + u1.y * u2.x;
    out.type = turn > 0 ? EndpointType::Concave : EndpointType::Convex;

    // Covariance: n1.x = rho1 + e1, n2.x = rho2 + e2  =>  dx = M^-1 e, M = [n1; n2].
    const double v1 = offsetVarianceAt(before, c, sensorSigma);
    const double v2 = offsetVarianceAt(after, c, sensorSigma);
    const double det = before.normal.x * after.normal.y - before.normal.y * after.normal.x;
    // Columns of M^-1: (n2.y, -n2.x)/det for e1 and (-n1.y, n1.x)/det for e2.
    const double ax = after.normal.y / det, ay = -after.normal.x / det;
    const double bx = -before.normal.y / det, by = before.normal.x / det;
    out.covariance(0, 0) = v1 * ax * ax + v2 * bx * bx;
    out.covariance(0, 1) = v1 * ax * ay + v2 * bx * by;
    out.covariance(1, 0) = out.covariance(0, 1);
    out.covariance(1, 1) = v1 * ay * ay + v2 * by * by;
    return true;
}

}  // namespace toposlam::features
