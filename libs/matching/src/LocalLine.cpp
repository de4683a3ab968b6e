#include <toposlam/matching/LocalLine.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toposlam::matching {

namespace {
/// Largest minor/major eigenvalue ratio of a neighbourhood that is still read as a line:
/// 1 cm noise on 5 points 20 cm apart gives ~0.01; a right-angle corner ~0.3.
constexpr double kMaxFlatness = 0.05;
/// Readings spread evenly over a length L have a variance of L^2 / 12 along it; noise sigma
/// across it stays under kMaxFlatness of that once L >= sqrt(12 / kMaxFlatness) sigma = 15.5
/// sigma: 8 sigma on each side.
constexpr double kReachInSigmas = 8;
constexpr long kMinBeams = 2, kMaxBeams = 16;  ///< neighbours on each side
/// Median of |N(0, 1)| (0.6745) times the spread of a reading from its neighbours' chord
/// (sqrt(1 + 1/4 + 1/4)): median distance from the chord / this = sigma.
const double kMedianToSigma = 0.6745 * std::sqrt(1.5);
}  // namespace

double surfaceNoise(const PolarScan& scan, double maxJoinDistance) {
    thread_local std::vector<double> distances;  // reused: no allocation per scan
    distances.clear();
    for (std::size_t b = 1; b + 1 < scan.size(); ++b) {
        if (!scan.valid(b - 1) || !scan.valid(b) || !scan.valid(b + 1))
            continue;
        const mrpt::math::TPoint2D &a = scan.point(b - 1), &p = scan.point(b),
                                   &c = scan.point(b + 1);
        const double ex = c.x - a.x, ey = c.y - a.y, chord = std::hypot(ex, ey);
        if (chord <= 0 || chord > 2 * jumpGap(scan, scan.range(b), maxJoinDistance))
            continue;
        const double mx = p.x - 0.5 * (a.x + c.x), my = p.y - 0.5 * (a.y + c.y);
        distances.push_back(std::abs(mx * ey - my * ex) / chord);
    }
    if (distances.size() < 10)
        return 0;
    const auto middle = distances.begin() + long(distances.size() / 2);
    std::nth_element(distances.begin(), middle, distances.end());
    return *middle / kMedianToSigma;
}

double localLineReach(double noise) {
    return kReachInSigmas * noise;
}

std::optional<LocalLine> fitLocalLine(const PolarScan& scan, std::size_t beam,
                                      double maxJoinDistance, double reach) {
    const mrpt::math::TPoint2D& p = scan.point(beam);
    const double join = jumpGap(scan, scan.range(beam), maxJoinDistance);
    // Squared distances against squared limits: no root per neighbour (this runs for every
    // reading of every scan that goes into a map).
    const double join2 = join * join, reach2 = reach * reach;
    // Neighbours on each side, walking outwards and stopping at a jump or at `reach`.
    double sx = p.x, sy = p.y, sxx = p.x * p.x, sxy = p.x * p.y, syy = p.y * p.y;
    int count = 1;
    for (long dir : {-1L, 1L}) {
        mrpt::math::TPoint2D last = p;
        for (long k = 1; k <= kMaxBeams; ++k) {
            const long q = scan.neighbour(long(beam), dir * k);
            if (q < 0 || !scan.valid(std::size_t(q)))
                break;
            const mrpt::math::TPoint2D& o = scan.point(std::size_t(q));
            const double jx = o.x - last.x, jy = o.y - last.y;
            if (jx * jx + jy * jy > join2)
                break;
            sx += o.x, sy += o.y, sxx += o.x * o.x, sxy += o.x * o.y, syy += o.y * o.y;
            ++count;
            last = o;
            const double rx = o.x - p.x, ry = o.y - p.y;
            if (k >= kMinBeams && rx * rx + ry * ry >= reach2)
                break;
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
