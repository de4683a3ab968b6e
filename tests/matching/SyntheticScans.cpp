#include "SyntheticScans.h"

#include <cmath>
#include <limits>

namespace toposlam::test {

using mrpt::math::TPoint2D;

simulation::LaserModel fullCircleLaser(std::size_t beams, double maxRange) {
    simulation::LaserModel laser;
    laser.beams = beams;
    laser.aperture = 2 * M_PI * double(beams - 1) / double(beams);
    laser.maxRange = maxRange;
    return laser;
}

namespace {
double distanceToWall(const simulation::WallSegment& w, const TPoint2D& p) {
    const double dx = w.b.x - w.a.x, dy = w.b.y - w.a.y;
    const double len2 = dx * dx + dy * dy;
    double t = ((p.x - w.a.x) * dx + (p.y - w.a.y) * dy) / len2;
    t = std::max(0.0, std::min(1.0, t));
    return std::hypot(p.x - w.a.x - t * dx, p.y - w.a.y - t * dy);
}

features::LineSegment makeSegment(const simulation::WallSegment& wall,
                                  const mrpt::poses::CPose2D& sensor, const TPoint2D& first,
                                  const TPoint2D& last, std::size_t b0, std::size_t b1) {
    // Wall in the sensor frame; end points = projections of the first / last points.
    const mrpt::poses::CPose2D inv = -sensor;
    TPoint2D a, b;
    inv.composePoint(wall.a.x, wall.a.y, a.x, a.y);
    inv.composePoint(wall.b.x, wall.b.y, b.x, b.y);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    const double ux = dx / len, uy = dy / len;
    const auto project = [&](const TPoint2D& p) {
        const double t = (p.x - a.x) * ux + (p.y - a.y) * uy;
        return TPoint2D(a.x + t * ux, a.y + t * uy);
    };
    features::LineSegment s;
    s.start = project(first);
    s.end = project(last);
    // Normal form x cos(theta) + y sin(theta) = rho with rho >= 0.
    double nx = -uy, ny = ux;
    double rho = nx * a.x + ny * a.y;
    if (rho < 0)
        nx = -nx, ny = -ny, rho = -rho;
    s.line.theta = std::atan2(ny, nx);
    s.line.rho = rho;
    s.firstBeam = std::uint32_t(b0);
    s.lastBeam = std::uint32_t(b1);
    return s;
}
}  // namespace

SyntheticScan simulateWithSegments(const simulation::PolygonWorld& world,
                                   const simulation::LaserModel& laser,
                                   const mrpt::poses::CPose2D& robotPose, std::size_t minBeams) {
    SyntheticScan out;
    std::mt19937 rng(7);
    out.observation = simulation::simulateScan(world, laser, robotPose, rng);
    out.polar.assign(out.observation);

    // Which wall each valid beam hit (-1: none, e.g. a disc).
    const std::size_t n = out.polar.size();
    std::vector<long> wallOf(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        if (!out.polar.valid(i))
            continue;
        TPoint2D w;
        robotPose.composePoint(out.polar.point(i).x, out.polar.point(i).y, w.x, w.y);
        double best = 1e-6;
        for (std::size_t k = 0; k < world.segments().size(); ++k) {
            const double d = distanceToWall(world.segments()[k], w);
            if (d < best)
                best = d, wallOf[i] = long(k);
        }
    }
    // Runs of beams on the same wall; a run through beam 0 of a full circle is cut there,
    // as extractors do (segments span firstBeam <= lastBeam).
    for (std::size_t i = 0; i < n;) {
        if (wallOf[i] < 0) {
            ++i;
            continue;
        }
        std::size_t last = i;
        while (last + 1 < n && wallOf[last + 1] == wallOf[i])
            ++last;
        if (last - i + 1 >= minBeams) {
            out.features.segments.push_back(makeSegment(world.segments()[std::size_t(wallOf[i])],
                                                        robotPose, out.polar.point(i),
                                                        out.polar.point(last), i, last));
        }
        i = last + 1;
    }
    return out;
}

simulation::PolygonWorld asymmetricRoom() {
    simulation::PolygonWorld w;
    // L-shaped hall, 10 m x 7 m with a 4 m x 3 m notch.
    w.addPolygon({{0, 0}, {10, 0}, {10, 4}, {6, 4}, {6, 7}, {0, 7}});
    w.addPolygon({{2.0, 2.0}, {2.8, 2.0}, {2.8, 2.6}, {2.0, 2.6}});  // pillar box
    w.addPolygon({{7.5, 1.0}, {9.0, 1.3}, {8.8, 2.1}, {7.3, 1.8}});  // table, skewed
    w.addPolygon({{1.0, 5.2}, {3.5, 5.2}, {3.5, 5.6}, {1.0, 5.6}});  // shelf
    return w;
}

}  // namespace toposlam::test
