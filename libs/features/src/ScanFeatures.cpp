#include <mrpt/math/wrap2pi.h>
#include <toposlam/features/ScanFeatures.h>

#include <cmath>

namespace toposlam::features {

using mrpt::math::TPoint2D;

double Line2D::distance(const TPoint2D& p) const {
    return p.x * std::cos(theta) + p.y * std::sin(theta) - rho;
}

TPoint2D Line2D::project(const TPoint2D& p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double d = p.x * c + p.y * s - rho;
    return {p.x - d * c, p.y - d * s};
}

Line2D Line2D::through(const TPoint2D& a, const TPoint2D& b) {
    // The normal is the direction a->b turned by -90 deg; flip it so that rho >= 0.
    Line2D l;
    l.theta = std::atan2(-(b.x - a.x), b.y - a.y);
    l.rho = a.x * std::cos(l.theta) + a.y * std::sin(l.theta);
    if (l.rho < 0) {
        l.rho = -l.rho;
        l.theta = mrpt::math::wrapToPi(l.theta + M_PI);
    }
    return l;
}

double LineSegment::length() const {
    return std::hypot(end.x - start.x, end.y - start.y);
}

TPoint2D LineSegment::midpoint() const {
    return {0.5 * (start.x + end.x), 0.5 * (start.y + end.y)};
}

void ScanFeatures::clear() {
    segments.clear();
    corners.clear();
    endpoints.clear();
}

ScanFeatures ScanFeatures::transformed(const mrpt::poses::CPose2D& pose) const {
    const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
    const auto move = [&](const TPoint2D& p) {
        return TPoint2D(pose.x() + c * p.x - s * p.y, pose.y() + s * p.x + c * p.y);
    };
    ScanFeatures out = *this;
    for (LineSegment& seg : out.segments) {
        seg.start = move(seg.start);
        seg.end = move(seg.end);
        // The normal turns with the pose; the offset grows by the translation along it.
        Line2D& l = seg.line;
        l.theta = mrpt::math::wrapToPi(l.theta + pose.phi());
        l.rho += pose.x() * std::cos(l.theta) + pose.y() * std::sin(l.theta);
        if (l.rho < 0) {
            l.rho = -l.rho;
            l.theta = mrpt::math::wrapToPi(l.theta + M_PI);
        }
    }
    for (Corner& corner : out.corners) {
        corner.position = move(corner.position);
        // R C R^T for the rotation R of the pose.
        const auto& C = corner.covariance;
        const double a = C(0, 0), b = C(0, 1), d = C(1, 1);
        corner.covariance(0, 0) = c * c * a - 2 * c * s * b + s * s * d;
        corner.covariance(0, 1) = c * s * (a - d) + (c * c - s * s) * b;
        corner.covariance(1, 0) = corner.covariance(0, 1);
        corner.covariance(1, 1) = s * s * a + 2 * c * s * b + c * c * d;
    }
    for (Endpoint& e : out.endpoints)
        e.position = move(e.position);
    return out;
}

const char* toString(EndpointType t) {
    switch (t) {
        case EndpointType::Convex:
            return "convex";
        case EndpointType::Concave:
            return "concave";
        case EndpointType::Jump:
            return "jump";
        case EndpointType::Open:
            return "open";
    }
    return "?";
}

}  // namespace toposlam::features
