#include <toposlam/rooms/LineMerger.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace toposlam::rooms {

namespace {

/// A segment with what eqs. 5-7 ask of it computed once, not once per pair: merge() compares
/// every pair in every round. The same arithmetic as LineSegment's accessors, so the same merges.
struct Measured {
    LineSegment line;
    double length = 0;        ///< LineSegment::length()
    cv::Point3d homogeneous;  ///< LineSegment::homogeneous()
    double normalLength = 0;  ///< |(a, b)| of the homogeneous line
    cv::Point2f midpoint;     ///< LineSegment::midpoint()

    explicit Measured(const LineSegment& l) : line(l) { update(); }
    void update() {
        length = line.length();
        homogeneous = line.homogeneous();
        normalLength = std::hypot(homogeneous.x, homogeneous.y);
        midpoint = line.midpoint();
    }
    /// LineSegment::lineDistance, from the cached line (a point-like segment: its own).
    double lineDistance(const cv::Point2f& p) const {
        const cv::Point3d& l = homogeneous;
        return normalLength > 0 ? std::abs(l.x * p.x + l.y * p.y + l.z) / normalLength
                                : line.lineDistance(p);
    }
};

/// Eq. 5 with |cos|: segments are undirected, so 179 deg apart means 1 deg apart. True when the
/// angle between them is at least maxAngle (rad), whose cosine is cosMaxAngle.
bool tooSteep(const Measured& a, const Measured& b, double maxAngle, double cosMaxAngle) {
    const double na = a.normalLength, nb = b.normalLength;
    if (na == 0 || nb == 0)
        return 0 >= maxAngle;
    const cv::Point3d &la = a.homogeneous, &lb = b.homogeneous;
    const double c = std::min(1.0, std::abs(la.x * lb.x + la.y * lb.y) / (na * nb));
    // acos decreases: away from the threshold the cosine decides (most pairs are far from
    // parallel); near it, acos itself, so a pair at the threshold is judged as it always was.
    constexpr double kMargin = 1e-9;
    if (c < cosMaxAngle - kMargin)
        return true;
    if (c > cosMaxAngle + kMargin)
        return false;
    return std::acos(c) >= maxAngle;
}

bool mergeable(const Measured& base, const Measured& candidate, double maxAngle, double cosMaxAngle,
               double maxDistancePx) {
    if (tooSteep(base, candidate, maxAngle, cosMaxAngle))
        return false;  // eq. 5
    const double meanDistance =
        0.5 * (base.lineDistance(candidate.line.start) + base.lineDistance(candidate.line.end));
    if (meanDistance >= maxDistancePx)
        return false;  // eq. 6
    const cv::Point2f dm = base.midpoint - candidate.midpoint;
    return std::hypot(dm.x, dm.y) < 0.5 * (base.length + candidate.length);  // eq. 7
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
    return mergeable(Measured(base), Measured(candidate), maxAngleRad, std::cos(maxAngleRad),
                     maxDistancePx);
}

std::vector<LineSegment> LineMerger::merge(std::vector<LineSegment> lines,
                                           double resolution) const {
    const double maxAngle = options_.maxAngleDeg * M_PI / 180.0;
    const double cosMaxAngle = std::cos(maxAngle);
    const double maxDistance = options_.maxDistance / resolution;
    std::vector<Measured> measured;
    measured.reserve(lines.size());
    for (const LineSegment& l : lines)
        measured.emplace_back(l);
    std::vector<bool> gone;
    bool merged = true;
    while (merged) {
        merged = false;
        // Longest first: the base of a merge is the longer, better-determined segment.
        std::sort(measured.begin(), measured.end(),
                  [](const Measured& a, const Measured& b) { return a.length > b.length; });
        gone.assign(measured.size(), false);
        for (std::size_t i = 0; i < measured.size(); ++i) {
            if (gone[i])
                continue;
            for (std::size_t j = i + 1; j < measured.size(); ++j) {
                if (gone[j] ||
                    !mergeable(measured[i], measured[j], maxAngle, cosMaxAngle, maxDistance))
                    continue;
                absorb(measured[i].line, measured[j].line);
                measured[i].update();
                gone[j] = true;
                merged = true;
            }
        }
        std::size_t k = 0;
        for (std::size_t i = 0; i < measured.size(); ++i) {
            if (!gone[i])
                measured[k++] = measured[i];
        }
        measured.erase(measured.begin() + static_cast<std::ptrdiff_t>(k), measured.end());
    }
    lines.clear();
    for (const Measured& m : measured)
        lines.push_back(m.line);
    return lines;
}

}  // namespace toposlam::rooms
