#include <toposlam/features/ArcCornerTest.h>
#include <toposlam/features/LineFit.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

namespace {
struct CircleSums {
    double ox = 0, oy = 0;
    double n = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0, xz = 0, yz = 0, z = 0, zz = 0;
    void add(double px, double py) {
        px -= ox;
        py -= oy;
        const double pz = px * px + py * py;
        n += 1;
        x += px;
        y += py;
        xx += px * px;
        xy += px * py;
        yy += py * py;
        xz += px * pz;
        yz += py * pz;
        z += pz;
        zz += pz * pz;
    }
};

/// Solves a x = b; false when a is singular (a degenerate point set).
bool solve3(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, Eigen::Vector3d& x) {
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(a);
    if (!lu.isInvertible())
        return false;
    x = lu.solve(b);
    return x.allFinite();
}
}  // namespace

bool ArcCornerTest::isArc(const ScanPoints& pts, std::size_t a0, std::size_t a1, std::size_t b0,
                          std::size_t b1, double lineRss, double sigma) const {
    CircleSums s;
    s.ox = pts.x(a1);  // near the joint: keeps the sums well conditioned
    s.oy = pts.y(a1);
    for (std::size_t k = a0; k <= a1; ++k)
        s.add(pts.x(k), pts.y(k));
    for (std::size_t k = b0; k <= b1; ++k)
        s.add(pts.x(k), pts.y(k));
    if (s.n < 5)
        return false;
    // Circle x^2 + y^2 + D x + E y + F = 0, least squares in D, E, F (3x3 normal equations,
    // solved by LU).
    Eigen::Matrix3d normal;
    normal << s.xx, s.xy, s.x, s.xy, s.yy, s.y, s.x, s.y, s.n;
    Eigen::Vector3d sol;
    if (!solve3(normal, Eigen::Vector3d(-s.xz, -s.yz, -s.z), sol))
        return false;
    const double D = sol(0), E = sol(1), F = sol(2);
    const double radius2 = 0.25 * (D * D + E * E) - F;
    // Far too large a circle (a straight-ish pair of walls): no arc of interest.
    if (!(radius2 > 0) || radius2 > 4 * maxRadius * maxRadius)
        return false;
    // The circle has 3 parameters, the two lines 4 (+ where they meet): prefer the circle
    // unless the lines explain the readings better by more than the extra parameters do by
    // chance (about 2 sigma^2 each, as in Akaike's criterion).
    const double allowed = lineRss + 4 * sigma * sigma;
    // The algebraic residual (z + D x + E y + F)^2, expanded in the sums, is about (2R)^2 times
    // the geometric one: a cheap first verdict on circles that clearly do not fit.
    const double algebraicRss = s.zz + D * D * s.xx + E * E * s.yy + F * F * s.n + 2 * D * s.xz +
                                2 * E * s.yz + 2 * F * s.z + 2 * D * E * s.xy + 2 * D * F * s.x +
                                2 * E * F * s.y;
    if (algebraicRss / (4 * radius2) > 20 * allowed)
        return false;
    // Geometric residual of the algebraic circle, then Gauss-Newton on the geometric one (the
    // algebraic fit is biased towards small circles on short noisy arcs). Each pass gives the
    // residual at the current circle and the normal equations for the next step. Clear cases
    // stop early: a circle already good enough, or one far worse than the lines.
    double cx = s.ox - 0.5 * D, cy = s.oy - 0.5 * E, radius = std::sqrt(radius2);
    {  // the algebraic circle alone decides the clear cases
        double rss = 0;
        const auto add = [&](std::size_t k) {
            const double r = std::sqrt(sq2(pts.x(k) - cx, pts.y(k) - cy)) - radius;
            rss += r * r;
        };
        for (std::size_t k = a0; k <= a1; ++k)
            add(k);
        for (std::size_t k = b0; k <= b1; ++k)
            add(k);
        if (rss <= allowed)
            return radius <= maxRadius;
        if (rss > 10 * allowed)
            return false;  // no refinement would make this circle fit
    }
    double bestRss = HUGE_VAL, bestRadius = radius;
    for (int iteration = 0; iteration < 6; ++iteration) {
        Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
        Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
        double rss = 0;
        const auto add = [&](std::size_t k) {
            const double dx = pts.x(k) - cx, dy = pts.y(k) - cy, d = std::sqrt(sq2(dx, dy));
            if (!(d > 0))
                return;
            const double inv = 1 / d, jx = -dx * inv, jy = -dy * inv, r = d - radius;
            rss += r * r;
            jtr(0) += jx * r;
            jtr(1) += jy * r;
            jtr(2) -= r;
            jtj(0, 0) += jx * jx;
            jtj(0, 1) += jx * jy;
            jtj(0, 2) -= jx;
            jtj(1, 1) += jy * jy;
            jtj(1, 2) -= jy;
            jtj(2, 2) += 1;
        };
        for (std::size_t k = a0; k <= a1; ++k)
            add(k);
        for (std::size_t k = b0; k <= b1; ++k)
            add(k);
        jtj(1, 0) = jtj(0, 1);
        jtj(2, 0) = jtj(0, 2);
        jtj(2, 1) = jtj(1, 2);
        if (!(rss < bestRss))
            break;  // the last step made it worse: keep the best
        bestRss = rss;
        bestRadius = radius;
        if (rss <= allowed)
            break;  // an arc
        Eigen::Vector3d step;
        if (!solve3(jtj, -jtr, step))
            break;
        cx += step(0);
        cy += step(1);
        radius += step(2);
    }
    return bestRadius > 0 && bestRadius <= maxRadius && bestRss <= allowed;
}

}  // namespace toposlam::features
