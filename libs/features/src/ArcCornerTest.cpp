#include <toposlam/features/ArcCornerTest.h>

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
}  // namespace

bool ArcCornerTest::isArc(const ScanPoints& pts, std::size_t a0, std::size_t a1, std::size_t b0,
                          std::size_t b1, double lineRms) const {
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
    // Cramer's rule).
    const double m[3][3] = {{s.xx, s.xy, s.x}, {s.xy, s.yy, s.y}, {s.x, s.y, s.n}};
    const double r[3] = {-s.xz, -s.yz, -s.z};
    const auto det3 = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
               a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double det = det3(m);
    if (!(std::abs(det) > 1e-300))
        return false;
    double sol[3];
    for (int c = 0; c < 3; ++c) {
        double mc[3][3];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                mc[i][j] = j == c ? r[i] : m[i][j];
        }
        sol[c] = det3(mc) / det;
    }
    const double D = sol[0], E = sol[1], F = sol[2];
    const double radius2 = 0.25 * (D * D + E * E) - F;
    if (!(radius2 > 0) || radius2 > maxRadius * maxRadius)
        return false;
    // Mean squared algebraic residual (z + D x + E y + F)^2, expanded in the sums; the
    // geometric residual is about the algebraic one / (2 R).
    const double algebraic2 =
        (s.zz + D * D * s.xx + E * E * s.yy + F * F * s.n + 2 * D * s.xz + 2 * E * s.yz +
         2 * F * s.z + 2 * D * E * s.xy + 2 * D * F * s.x + 2 * E * F * s.y) /
        s.n;
    const double circleRms = std::sqrt(std::max(algebraic2, 0.0) / (4 * radius2));
    return circleRms <= lineRms;
}

}  // namespace toposlam::features
