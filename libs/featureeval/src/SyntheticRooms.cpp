#include <toposlam/featureeval/SyntheticRooms.h>

#include <algorithm>
#include <cmath>

namespace toposlam::featureeval {

using mrpt::math::TPoint2D;

namespace {

double pointSegmentDistance(const TPoint2D& p, const TPoint2D& a, const TPoint2D& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

bool segmentsCross(const TPoint2D& a, const TPoint2D& b, const TPoint2D& c, const TPoint2D& d) {
    const auto orient = [](const TPoint2D& p, const TPoint2D& q, const TPoint2D& r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

/// Smallest distance between the boundaries of two polygons (0 if they cross).
double polygonDistance(const Polygon& p, const Polygon& q) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const TPoint2D &a = p[i], &b = p[(i + 1) % p.size()];
        for (std::size_t j = 0; j < q.size(); ++j) {
            const TPoint2D &c = q[j], &d = q[(j + 1) % q.size()];
            if (segmentsCross(a, b, c, d))
                return 0;
            best = std::min({best, pointSegmentDistance(a, c, d), pointSegmentDistance(c, a, b)});
        }
    }
    return best;
}

double distanceToBoundary(const Polygon& poly, const TPoint2D& p) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        best = std::min(best, pointSegmentDistance(p, poly[i], poly[(i + 1) % poly.size()]));
    }
    return best;
}

Polygon transformed(const Polygon& poly, double cx, double cy, double yaw) {
    Polygon out;
    const double c = std::cos(yaw), s = std::sin(yaw);
    for (const TPoint2D& p : poly)
        out.emplace_back(cx + c * p.x - s * p.y, cy + s * p.x + c * p.y);
    return out;
}

}  // namespace

bool insidePolygon(const Polygon& poly, const TPoint2D& p) {
    bool inside = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const TPoint2D &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

simulation::PolygonWorld SyntheticScene::world() const {
    simulation::PolygonWorld w;
    for (const Polygon& p : polygons)
        w.addPolygon(p);
    for (const simulation::Disc& d : discs)
        w.addDisc(d);
    return w;
}

namespace {

/// A W x D rectangle, counter-clockwise from (0, 0), maybe with a rectangular bite out of one
/// corner (notch) and another corner cut off (chamfer).
Polygon roomOutline(std::mt19937& rng, const SyntheticRoomOptions& o, double W, double D) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto uniform = [&](double a, double b) { return a + (b - a) * unit(rng); };
    std::vector<Polygon> corner(4);
    corner[0] = {{0, 0}};
    corner[1] = {{W, 0}};
    corner[2] = {{W, D}};
    corner[3] = {{0, D}};
    const int notchAt = unit(rng) < o.notchProbability ? static_cast<int>(rng() % 4) : -1;
    int chamferAt = unit(rng) < o.chamferProbability ? static_cast<int>(rng() % 4) : -1;
    if (chamferAt == notchAt)
        chamferAt = -1;
    if (notchAt >= 0) {
        // Replace the corner by three: a rectangular bite of the room.
        const double w = uniform(0.25, 0.45) * W, d = uniform(0.25, 0.45) * D;
        const TPoint2D c = corner[notchAt][0];
        const double sx = c.x > 0 ? -1 : 1, sy = c.y > 0 ? -1 : 1;  // towards the inside
        const TPoint2D alongY(c.x, c.y + sy * d), inner(c.x + sx * w, c.y + sy * d),
            alongX(c.x + sx * w, c.y);
        // Counter-clockwise order: corners 0 and 2 are entered along y, 1 and 3 along x.
        if (notchAt == 0 || notchAt == 2) {
            corner[notchAt] = {alongY, inner, alongX};
        } else {
            corner[notchAt] = {alongX, inner, alongY};
        }
    }
    if (chamferAt >= 0) {
        const double cut = uniform(0.5, 1.2);
        const TPoint2D c = corner[chamferAt][0];
        const double sx = c.x > 0 ? -1 : 1, sy = c.y > 0 ? -1 : 1;
        const TPoint2D onY(c.x, c.y + sy * cut), onX(c.x + sx * cut, c.y);
        if (chamferAt == 0 || chamferAt == 2) {
            corner[chamferAt] = {onY, onX};
        } else {
            corner[chamferAt] = {onX, onY};
        }
    }
    Polygon room;
    for (const Polygon& c : corner)
        room.insert(room.end(), c.begin(), c.end());
    return room;
}

/// Reverses the furniture polygons (all but the first, the room) that run clockwise.
void makeFurnitureCounterClockwise(std::vector<Polygon>& polygons) {
    for (std::size_t i = 1; i < polygons.size(); ++i) {
        Polygon& p = polygons[i];
        double area2 = 0;
        for (std::size_t k = 0; k < p.size(); ++k) {
            const TPoint2D &a = p[k], &b = p[(k + 1) % p.size()];
            area2 += a.x * b.y - b.x * a.y;
        }
        if (area2 < 0)
            std::reverse(p.begin(), p.end());
    }
}

}  // namespace

SyntheticScene makeSyntheticRoom(std::mt19937& rng, const SyntheticRoomOptions& o) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto uniform = [&](double a, double b) { return a + (b - a) * unit(rng); };
    SyntheticScene scene;

    // Room outline, counter-clockwise, corners 0:(0,0) 1:(W,0) 2:(W,D) 3:(0,D).
    const double W = uniform(o.minWidth, o.maxWidth), D = uniform(o.minDepth, o.maxDepth);
    Polygon room = roomOutline(rng, o, W, D);
    const double roomYaw = uniform(-M_PI, M_PI);
    // Draws are sequenced (a call's arguments are evaluated in an order of the compiler's
    // choosing): y before x, the order GCC gave them when both were arguments.
    const double roomY = uniform(-3, 3), roomX = uniform(-3, 3);
    room = transformed(room, roomX, roomY, roomYaw);
    scene.polygons.push_back(room);

    double minX = HUGE_VAL, maxX = -HUGE_VAL, minY = HUGE_VAL, maxY = -HUGE_VAL;
    for (const TPoint2D& p : room) {
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }

    // Furniture: boxes and triangles, clear of the walls and of each other.
    const int wanted =
        o.minFurniture +
        static_cast<int>(rng() % static_cast<unsigned>(o.maxFurniture - o.minFurniture + 1));
    for (int attempt = 0; attempt < 200 && static_cast<int>(scene.polygons.size()) - 1 < wanted;
         ++attempt) {
        Polygon shape;
        if (unit(rng) < o.triangleProbability) {
            // Isosceles triangle, apex angle 50..100 deg, legs 0.5..1.2 m.
            const double apex = uniform(50, 100) * M_PI / 180, leg = uniform(0.5, 1.2);
            shape = {{0, 0}, {leg, -leg * std::tan(apex / 2)}, {leg, leg * std::tan(apex / 2)}};
            for (TPoint2D& p : shape)
                p.x -= 2 * leg / 3;
        } else {
            const double a = uniform(0.4, 1.6) / 2, b = uniform(0.4, 1.0) / 2;
            shape = {{-a, -b}, {a, -b}, {a, b}, {-a, b}};
        }
        const double yaw =
            unit(rng) < 0.5 ? roomYaw + (rng() % 4) * M_PI / 2 : uniform(-M_PI, M_PI);
        const double y = uniform(minY, maxY), x = uniform(minX, maxX);
        const Polygon piece = transformed(shape, x, y, yaw);
        bool ok = true;
        for (const TPoint2D& p : piece)
            ok = ok && insidePolygon(room, p);
        for (const Polygon& other : scene.polygons) {
            ok = ok && polygonDistance(piece, other) >= o.clearance;
        }
        if (ok)
            scene.polygons.push_back(piece);
    }
    makeFurnitureCounterClockwise(scene.polygons);

    // Pillars.
    const int pillars = o.maxPillars > 0 ? static_cast<int>(rng() % (o.maxPillars + 1)) : 0;
    for (int attempt = 0; attempt < 100 && static_cast<int>(scene.discs.size()) < pillars;
         ++attempt) {
        simulation::Disc d{{uniform(minX, maxX), uniform(minY, maxY)}, uniform(0.1, 0.25)};
        bool ok = insidePolygon(room, d.centre) &&
                  distanceToBoundary(room, d.centre) >= d.radius + o.clearance;
        for (std::size_t i = 1; i < scene.polygons.size(); ++i) {
            ok = ok && !insidePolygon(scene.polygons[i], d.centre) &&
                 distanceToBoundary(scene.polygons[i], d.centre) >= d.radius + o.clearance;
        }
        if (ok)
            scene.discs.push_back(d);
    }

    // Sensor poses in the free space.
    for (int attempt = 0; attempt < 1000 && static_cast<int>(scene.poses.size()) < o.posesPerRoom;
         ++attempt) {
        const double y = uniform(minY, maxY), x = uniform(minX, maxX);
        const TPoint2D p(x, y);
        bool ok = insidePolygon(room, p) && distanceToBoundary(room, p) >= o.poseClearance;
        for (std::size_t i = 1; i < scene.polygons.size(); ++i) {
            ok = ok && !insidePolygon(scene.polygons[i], p) &&
                 distanceToBoundary(scene.polygons[i], p) >= o.poseClearance;
        }
        for (const simulation::Disc& d : scene.discs) {
            ok = ok && std::hypot(p.x - d.centre.x, p.y - d.centre.y) >= d.radius + o.poseClearance;
        }
        if (ok)
            scene.poses.emplace_back(p.x, p.y, uniform(-M_PI, M_PI));
    }
    return scene;
}

}  // namespace toposlam::featureeval
