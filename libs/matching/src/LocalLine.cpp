#include <toposlam/matching/LocalLine.h>

#include <cmath>

namespace toposlam::matching {

namespace {
/// Largest minor/major eigenvalue ratio of a neighbourhood that is still read as a line:
/// 1 cm noise on 5 points 20 cm apart gives ~0.01; a right-angle corner ~0.3.
constexpr double kMaxFlatness = 0.05;
}  // namespace

std::optional<LocalLine> fitLocalLine(const PolarScan& scan, std::size_t beam,
                                      double maxJoinDistance) {
    const mrpt::math::TPoint2D& p = scan.point(beam);
    const double join = maxJoinDistance + 3 * std::abs(scan.bearingStep()) * scan.range(beam);
    // Neighbours within +-2 beams, walking outwards and stopping at a jump.
    double sx = p.x, sy = p.y, sxx = p.x * p.x, sxy = p.x * p.y, syy = p.y * p.y;
    int count = 1;
    for (long dir : {-1L, 1L}) {
        mrpt::math::TPoint2D last = p;
        for (long k = 1; k <= 2; ++k) {
            const long q = scan.neighbour(long(beam), dir * k);
            if (q < 0 || !scan.valid(std::size_t(q)))
                break;
            const mrpt::math::TPoint2D& o = scan.point(std::size_t(q));
            if (std::hypot(o.x - last.x, o.y - last.y) > join)
                break;
            sx += o.x, sy += o.y, sxx += o.x * o.x, sxy += o.x * o.y, syy += o.y * o.y;
            ++count;
            last = o;
        }
    }
    if (count < 3)
        return std::nullopt;
    // Principal direction of the neighbourhood; the normal is the minor axis.
    const double mx = sx / count, my = sy / count;
    const double cxx = sxx / count - mx * mx, cxy = sxy / count - mx * my,
                 cyy = syy / count - my * my;
    const double theta = 0.5 * std::atan2(2 * cxy, cxx - cyy);  // major axis
    // Not a line where the neighbourhood bends (a corner, a leg): minor / major spread.
    const double mean = 0.5 * (cxx + cyy), radius = std::hypot(0.5 * (cxx - cyy), cxy);
    if (mean - radius > kMaxFlatness * (mean + radius))
        return std::nullopt;
    LocalLine l;
    l.nx = -std::sin(theta);
    l.ny = std::cos(theta);
    l.offset = l.nx * mx + l.ny * my;
    if (l.offset > 0)  // face the sensor
        l.nx = -l.nx, l.ny = -l.ny, l.offset = -l.offset;
    return l;
}

}  // namespace toposlam::matching
