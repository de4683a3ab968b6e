#include <toposlam/features/InscribedAngleArcTest.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

bool InscribedAngleArcTest::isArc(const ScanPoints& pts, std::size_t begin, std::size_t end) const {
    if (end < begin + 4)
        return false;
    const std::size_t margin = (end - begin) / 10;
    const double ax = pts.x(begin), ay = pts.y(begin), bx = pts.x(end), by = pts.y(end);
    double sum = 0, sum2 = 0;
    std::size_t m = 0;
    for (std::size_t k = begin + 1 + margin; k + 1 + margin <= end; ++k) {
        const double ux = ax - pts.x(k), uy = ay - pts.y(k);
        const double vx = bx - pts.x(k), vy = by - pts.y(k);
        const double angle = std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
        sum += angle;
        sum2 += angle * angle;
        ++m;
    }
    if (m < 3)
        return false;
    const double mean = sum / static_cast<double>(m);
    const double var = std::max(0.0, sum2 / static_cast<double>(m) - mean * mean);
    return mean >= minMeanAngle && mean <= maxMeanAngle && std::sqrt(var) < maxAngleStd;
}

}  // namespace toposlam::features
