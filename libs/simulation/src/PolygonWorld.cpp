#include <toposlam/simulation/PolygonWorld.h>
#include <toposlam/simulation/RayDiscIntersection.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

void PolygonWorld::addSegment(const TPoint2D& a, const TPoint2D& b) {
    segments_.push_back({a, b});
}

void PolygonWorld::addPolygon(const std::vector<TPoint2D>& vertices) {
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        addSegment(vertices[i], vertices[(i + 1) % vertices.size()]);
    }
}

void PolygonWorld::addDisc(const Disc& disc) {
    discs_.push_back(disc);
}

double PolygonWorld::castRay(const TPoint2D& origin, double angle, double maxRange) const {
    const double dx = std::cos(angle), dy = std::sin(angle);
    double best = std::numeric_limits<double>::infinity();

    // Ray o + t*d against segment a + s*(b-a): solve with 2D cross products.
    for (const WallSegment& w : segments_) {
        const double ex = w.b.x - w.a.x, ey = w.b.y - w.a.y;
        const double denom = dx * ey - dy * ex;
        if (std::abs(denom) < 1e-15)
            continue;  // parallel: grazing rays never return
        const double ox = w.a.x - origin.x, oy = w.a.y - origin.y;
        const double t = (ox * ey - oy * ex) / denom;
        const double s = (ox * dy - oy * dx) / denom;
        if (t > 0 && s >= 0 && s <= 1 && t < best)
            best = t;
    }
    for (const Disc& c : discs_) {
        best = std::min(best,
                        rayDiscEntry(origin.x, origin.y, dx, dy, c.centre.x, c.centre.y, c.radius));
    }
    return best <= maxRange ? best : std::numeric_limits<double>::infinity();
}

}  // namespace toposlam::simulation
