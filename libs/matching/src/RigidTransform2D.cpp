#include <toposlam/matching/RigidTransform2D.h>

#include <algorithm>
#include <cmath>

namespace toposlam::matching {

namespace {
/// Smallest / largest eigenvalue of the symmetric 2x2 [a b; b c].
double conditioning(double a, double b, double c) {
    const double mean = 0.5 * (a + c);
    const double radius = std::hypot(0.5 * (a - c), b);
    const double hi = mean + radius, lo = mean - radius;
    return hi > 0 ? std::max(0.0, lo) / hi : 0.0;
}
/// Unit eigenvector of the smaller eigenvalue of the symmetric 2x2 [a b; b c].
mrpt::math::TPoint2D weakestDirection(double a, double b, double c) {
    const double lo = 0.5 * (a + c) - std::hypot(0.5 * (a - c), b);
    double x = b, y = lo - a;  // (A - lo I) v = 0 from the first row
    if (std::hypot(x, y) < 1e-12 * (1 + std::abs(a) + std::abs(c)))
        x = lo - c, y = b;  // from the second row
    const double n = std::hypot(x, y);
    if (!(n > 0))
        return a <= c ? mrpt::math::TPoint2D(1, 0) : mrpt::math::TPoint2D(0, 1);
    return {x / n, y / n};
}
}  // namespace

TransformEstimate rigidTransformFromPoints(const std::vector<PointPair>& pairs) {
    TransformEstimate out;
    double W = 0, cx = 0, cy = 0, rx = 0, ry = 0;
    for (const PointPair& p : pairs) {
        W += p.weight;
        cx += p.weight * p.current.x;
        cy += p.weight * p.current.y;
        rx += p.weight * p.reference.x;
        ry += p.weight * p.reference.y;
    }
    if (!(W > 0))
        return out;
    cx /= W, cy /= W, rx /= W, ry /= W;
    // Rotation maximising sum w (r - r0) . R (c - c0); spread of the current points for the
    // conditioning.
    double sxx = 0, sxy = 0, syy = 0, dot = 0, crossSum = 0;
    for (const PointPair& p : pairs) {
        const double ax = p.current.x - cx, ay = p.current.y - cy;
        const double bx = p.reference.x - rx, by = p.reference.y - ry;
        dot += p.weight * (ax * bx + ay * by);
        crossSum += p.weight * (ax * by - ay * bx);
        sxx += p.weight * ax * ax;
        sxy += p.weight * ax * ay;
        syy += p.weight * ay * ay;
    }
    const double phi = std::atan2(crossSum, dot);
    const double c = std::cos(phi), s = std::sin(phi);
    out.pose = mrpt::poses::CPose2D(rx - (c * cx - s * cy), ry - (s * cx + c * cy), phi);
    out.valid = true;
    out.conditioning = conditioning(sxx, sxy, syy);
    const mrpt::math::TPoint2D w = weakestDirection(sxx, sxy, syy);  // current frame
    out.weakDirection = {c * w.x - s * w.y, s * w.x + c * w.y};
    return out;
}

TransformEstimate rigidTransformFromLines(const std::vector<LinePair>& pairs) {
    TransformEstimate out;
    double sinSum = 0, cosSum = 0;
    for (const LinePair& p : pairs) {
        // Angle from the current direction to the reference direction.
        const double c = p.currentDirection.x * p.referenceDirection.x +
                         p.currentDirection.y * p.referenceDirection.y;
        const double s = p.currentDirection.x * p.referenceDirection.y -
                         p.currentDirection.y * p.referenceDirection.x;
        sinSum += p.weight * s;
        cosSum += p.weight * c;
    }
    if (!(std::hypot(sinSum, cosSum) > 0))
        return out;
    const double phi = std::atan2(sinSum, cosSum);
    const double c = std::cos(phi), s = std::sin(phi);

    // Normal equations for t from the across-line constraints; only when they leave a
    // direction free, weak along-line midpoint constraints (weight kAlong) fill it in.
    constexpr double kAlong = 1e-3;
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    double n11 = 0, n12 = 0, n22 = 0, bn1 = 0, bn2 = 0;
    for (const LinePair& p : pairs) {
        const double nx = -p.referenceDirection.y, ny = p.referenceDirection.x;
        const double ux = p.referenceDirection.x, uy = p.referenceDirection.y;
        const double px = c * p.currentPoint.x - s * p.currentPoint.y;
        const double py = s * p.currentPoint.x + c * p.currentPoint.y;
        const double dx = p.referencePoint.x - px, dy = p.referencePoint.y - py;
        const double across = nx * dx + ny * dy, along = ux * dx + uy * dy;
        const double w = p.weight;
        n11 += w * nx * nx, n12 += w * nx * ny, n22 += w * ny * ny;
        bn1 += w * nx * across, bn2 += w * ny * across;
        a11 += w * (nx * nx + kAlong * ux * ux);
        a12 += w * (nx * ny + kAlong * ux * uy);
        a22 += w * (ny * ny + kAlong * uy * uy);
        b1 += w * (nx * across + kAlong * ux * along);
        b2 += w * (ny * across + kAlong * uy * along);
    }
    out.conditioning = conditioning(n11, n12, n22);
    out.weakDirection = weakestDirection(n11, n12, n22);
    if (out.conditioning > 1e-9) {  // the lines alone fix t: no midpoint bias at all
        a11 = n11, a12 = n12, a22 = n22, b1 = bn1, b2 = bn2;
    }
    const double det = a11 * a22 - a12 * a12;
    if (!(det > 0))
        return out;
    const double tx = (a22 * b1 - a12 * b2) / det, ty = (a11 * b2 - a12 * b1) / det;
    out.pose = mrpt::poses::CPose2D(tx, ty, phi);
    out.valid = true;
    return out;
}

}  // namespace toposlam::matching
