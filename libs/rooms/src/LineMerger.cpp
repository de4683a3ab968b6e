#include <toposlam/rooms/LineMerger.h>

#include <algorithm>
#include <cmath>

namespace toposlam::rooms {

namespace {

double angleBetween(const LineSegment& a, const LineSegment& b) {
    // Eq. 5 with |cos|: segments are undirected, so 179 deg apart means 1 deg apart.
    const cv::Point3d la = a.homogeneous(), lb = b.homogeneous();
    const double na = std::hypot(la.x, la.y), nb = std::hypot(lb.x, lb.y);
    if (na == 0 || nb == 0)
        return 0;
    const double c = std::min(1.0, std::abs(la.x * lb.x + la.y * lb.y) / (na * nb));
    return std::acos(c);
}

// Extends `base` along its own line so that it covers the projections of `other`'s endpoints.
void absorb(LineSegment& base, const LineSegment& other) {
    const cv::Point2f d = base.end - base.start;
    const double len = std::hypot(d.x, d.y);
    if (len == 0)
        return;
    const cv::Point2f u(static_cast<float>(d.x / len), static_cast<float>(d.y / len));
    auto along = [&](const cv::Point2f& p) { return static_cast<double>((p - base.start).dot(u)); };
    const double t0 = std::min({0.0, along(other.start), along(other.end)});
    const double t1 = std::max({len, along(other.start), along(other.end)});
    const cv::Point2f s = base.start;
    base.start = s + u * static_cast<float>(t0);
    base.end = s + u * static_cast<float>(t1);
}

}  // namespace

bool LineMerger::canMerge(const LineSegment& base, const LineSegment& candidate, double maxAngleRad,
                          double maxDistancePx) {
    if (angleBetween(base, candidate) >= maxAngleRad)
        return false;  // eq. 5
    const double meanDistance =
        0.5 * (base.lineDistance(candidate.start) + base.lineDistance(candidate.end));
    if (meanDistance >= maxDistancePx)
        return false;  // eq. 6
    const cv::Point2f dm = base.midpoint() - candidate.midpoint();
    return std::hypot(dm.x, dm.y) < 0.5 * (base.length() + candidate.length());  // eq. 7
}

std::vector<LineSegment> LineMerger::merge(std::vector<LineSegment> lines,
                                           double resolution) const {
    const double maxAngle = options_.maxAngleDeg * M_PI / 180.0;
    const double maxDistance = options_.maxDistance / resolution;
    bool merged = true;
    while (merged) {
        merged = false;
        // Longest first: the base of a merge is the longer, better-determined segment.
        std::sort(lines.begin(), lines.end(), [](const LineSegment& a, const LineSegment& b) {
            return a.length() > b.length();
        });
        std::vector<bool> gone(lines.size(), false);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (gone[i])
                continue;
            for (std::size_t j = i + 1; j < lines.size(); ++j) {
                if (gone[j] || !canMerge(lines[i], lines[j], maxAngle, maxDistance))
                    continue;
                absorb(lines[i], lines[j]);
                gone[j] = true;
                merged = true;
            }
        }
        std::size_t k = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (!gone[i])
                lines[k++] = lines[i];
        }
        lines.resize(k);
    }
    return lines;
}

}  // namespace toposlam::rooms
