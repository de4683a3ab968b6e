#include <mrpt/math/wrap2pi.h>
#include <toposlam/matching/AttributedGraph.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace toposlam::matching {

using mrpt::math::TPoint2D;

namespace {
double pointToSegment(const TPoint2D& p, const TPoint2D& a, const TPoint2D& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double cross(const TPoint2D& o, const TPoint2D& a, const TPoint2D& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
}  // namespace

double segmentDistance(const TPoint2D& a0, const TPoint2D& a1, const TPoint2D& b0,
                       const TPoint2D& b1) {
    // Proper crossing: each segment's ends lie on opposite sides of the other.
    const double d1 = cross(a0, a1, b0), d2 = cross(a0, a1, b1);
    const double d3 = cross(b0, b1, a0), d4 = cross(b0, b1, a1);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 0.0;
    return std::min({pointToSegment(a0, b0, b1), pointToSegment(a1, b0, b1),
                     pointToSegment(b0, a0, a1), pointToSegment(b1, a0, a1)});
}

void AttributedGraph::build(const std::vector<features::LineSegment>& segments, double minLength,
                            std::size_t maxNodes) {
    // Length threshold that keeps at most maxNodes segments (the longest ones).
    lengths_.clear();
    for (const features::LineSegment& seg : segments) {
        const double length = std::hypot(seg.end.x - seg.start.x, seg.end.y - seg.start.y);
        if (length > 0 && length >= minLength)
            lengths_.push_back(length);
    }
    double threshold = minLength;
    if (lengths_.size() > maxNodes && maxNodes > 0) {
        std::nth_element(lengths_.begin(), lengths_.begin() + long(maxNodes - 1), lengths_.end(),
                         std::greater<double>());
        threshold = std::max(threshold, lengths_[maxNodes - 1]);
    }

    nodes_.clear();
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const features::LineSegment& seg = segments[s];
        const double dx = seg.end.x - seg.start.x, dy = seg.end.y - seg.start.y;
        const double length = std::hypot(dx, dy);
        if (!(length > 0) || length < threshold)
            continue;
        if (maxNodes == 0 || nodes_.size() >= maxNodes)
            break;
        SegmentNode n;
        n.start = seg.start;
        n.end = seg.end;
        n.midpoint = {0.5 * (seg.start.x + seg.end.x), 0.5 * (seg.start.y + seg.end.y)};
        n.direction = {dx / length, dy / length};
        n.normal = {-n.direction.y, n.direction.x};
        n.heading = std::atan2(dy, dx);
        n.length = length;
        n.offset = n.normal.x * n.midpoint.x + n.normal.y * n.midpoint.y;
        n.firstBeam = seg.firstBeam;
        n.lastBeam = seg.lastBeam;
        n.segment = static_cast<std::uint32_t>(s);
        nodes_.push_back(n);
    }

    const std::size_t n = nodes_.size();
    edges_.resize(n * n);
    for (std::size_t i = 0; i < n; ++i) {
        const SegmentNode& a = nodes_[i];
        edges_[i * n + i] = {0, 0, 0, 0};
        for (std::size_t j = i + 1; j < n; ++j) {
            const SegmentNode& b = nodes_[j];
            const double angle = mrpt::math::wrapToPi(b.heading - a.heading);
            const double ratio = (a.length - b.length) / std::max(a.length, b.length);
            const double mid = std::hypot(b.midpoint.x - a.midpoint.x, b.midpoint.y - a.midpoint.y);
            const double closest = segmentDistance(a.start, a.end, b.start, b.end);
            edges_[i * n + j] = {angle, ratio, mid, closest};
            // The reverse edge: angle and length ratio change sign (pi stays pi).
            edges_[j * n + i] = {angle == M_PI ? M_PI : -angle, -ratio, mid, closest};
        }
    }
}

}  // namespace toposlam::matching
