#include <toposlam/featureeval/FeatureGroundTruth.h>

#include <cmath>

namespace toposlam::featureeval {

using mrpt::math::TPoint2D;

namespace {

struct Edge {
    TPoint2D a, b;
};

/// Exact ray cast that also says what it hit: edge index, -2 for a disc, -1 for nothing.
double castRay(const std::vector<Edge>& edges, const std::vector<simulation::Disc>& discs,
               const TPoint2D& o, double angle, double maxRange, int& hit) {
    const double dx = std::cos(angle), dy = std::sin(angle);
    double best = HUGE_VAL;
    hit = -1;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const Edge& w = edges[i];
        const double ex = w.b.x - w.a.x, ey = w.b.y - w.a.y;
        const double denom = dx * ey - dy * ex;
        if (std::abs(denom) < 1e-15)
            continue;
        const double ox = w.a.x - o.x, oy = w.a.y - o.y;
        const double t = (ox * ey - oy * ex) / denom, s = (ox * dy - oy * dx) / denom;
        if (t > 0 && s >= 0 && s <= 1 && t < best) {
            best = t;
            hit = static_cast<int>(i);
        }
    }
    for (const simulation::Disc& c : discs) {
        const double ox = o.x - c.centre.x, oy = o.y - c.centre.y;
        const double b = ox * dx + oy * dy;
        const double disc = b * b - (ox * ox + oy * oy - c.radius * c.radius);
        if (disc < 0)
            continue;
        const double t = -b - std::sqrt(disc);
        if (t > 0 && t < best) {
            best = t;
            hit = -2;
        }
    }
    if (best > maxRange)
        hit = -1;
    return best;
}

/// The edges of every polygon of `scene`, in order; firstEdge[p] = index of polygon p's first.
std::vector<Edge> polygonEdges(const SyntheticScene& scene, std::vector<std::size_t>& firstEdge) {
    std::vector<Edge> edges;
    for (const Polygon& p : scene.polygons) {
        firstEdge.push_back(edges.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            edges.push_back({p[i], p[(i + 1) % p.size()]});
    }
    return edges;
}

/// Runs of at least `minRunBeams` consecutive beams (counter-clockwise order k) on one edge.
template <typename ScanIndex>
std::vector<GroundTruthRun> wallRuns(const std::vector<int>& edgeOf,
                                     const std::vector<TPoint2D>& hitPoint, ScanIndex scanIndex,
                                     std::size_t minRunBeams) {
    std::vector<GroundTruthRun> runs;
    const std::size_t n = edgeOf.size();
    for (std::size_t k = 0; k < n;) {
        std::size_t e = k;
        while (e + 1 < n && edgeOf[e + 1] == edgeOf[k])
            ++e;
        if (edgeOf[k] >= 0 && e - k + 1 >= minRunBeams) {
            GroundTruthRun run;
            const std::size_t i0 = scanIndex(k), i1 = scanIndex(e);
            run.firstBeam = static_cast<std::uint32_t>(std::min(i0, i1));
            run.lastBeam = static_cast<std::uint32_t>(std::max(i0, i1));
            run.start = i0 < i1 ? hitPoint[k] : hitPoint[e];
            run.end = i0 < i1 ? hitPoint[e] : hitPoint[k];
            runs.push_back(run);
        }
        k = e + 1;
    }
    return runs;
}

}  // namespace

ScanGroundTruth computeGroundTruth(const SyntheticScene& scene,
                                   const mrpt::poses::CPose2D& sensorPose,
                                   const mrpt::obs::CObservation2DRangeScan& scan,
                                   const GroundTruthOptions& options) {
    ScanGroundTruth gt;
    const std::size_t n = scan.getScanSize();
    if (n < 2)
        return gt;
    std::vector<std::size_t> firstEdge;  // of each polygon
    const std::vector<Edge> edges = polygonEdges(scene, firstEdge);

    // Beams in counter-clockwise order k (scan index: k, or n-1-k for left-to-right scans).
    const auto scanIndex = [&](std::size_t k) { return scan.rightToLeft ? k : n - 1 - k; };
    const double step = static_cast<double>(scan.aperture) / static_cast<double>(n - 1);
    const double firstBearing = -0.5 * static_cast<double>(scan.aperture);
    const TPoint2D origin(sensorPose.x(), sensorPose.y());
    const double yaw = sensorPose.phi(), maxRange = scan.maxRange;
    std::vector<int> edgeOf(n);  // the edge each beam hits (-1: none), and where (sensor frame)
    std::vector<TPoint2D> hitPoint(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double bearing = scan.getScanAngle(scanIndex(k));  // the simulator's own angle
        const double t = castRay(edges, scene.discs, origin, yaw + bearing, maxRange, edgeOf[k]);
        hitPoint[k] = std::isfinite(t) ? TPoint2D(t * std::cos(bearing), t * std::sin(bearing))
                                       : TPoint2D(0, 0);
    }

    // Consecutive hits on one wall are one continuous surface when closer than the graph
    // paper's jump distance k psi d (k = 15): the wall is seen at less than 86 deg incidence.
    const auto continuous = [&](std::size_t k1, std::size_t k2) {
        const TPoint2D &p = hitPoint[k1], &q = hitPoint[k2];
        const double d = std::min(std::hypot(p.x, p.y), std::hypot(q.x, q.y));
        return std::hypot(p.x - q.x, p.y - q.y) <= 15.0 * step * d;
    };

    // Corners.
    const double c = std::cos(yaw), s = std::sin(yaw);
    for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
        const Polygon& poly = scene.polygons[p];
        const std::size_t m = poly.size();
        for (std::size_t j = 0; j < m; ++j) {
            const TPoint2D& v = poly[j];
            const int edgeBefore = static_cast<int>(firstEdge[p] + (j + m - 1) % m);
            const int edgeAfter = static_cast<int>(firstEdge[p] + j);
            const double dx = v.x - origin.x, dy = v.y - origin.y;
            const TPoint2D local(c * dx + s * dy, -s * dx + c * dy);
            const double range = std::hypot(local.x, local.y);
            if (range >= maxRange)
                continue;
            const double bearing = std::atan2(local.y, local.x);
            // Nearest beams strictly on each side of the vertex's bearing.
            const double pos = (bearing - firstBearing) / step;
            if (pos <= 0 || pos >= static_cast<double>(n - 1))
                continue;
            std::size_t below = static_cast<std::size_t>(std::floor(pos));
            std::size_t above = below + 1;
            if (std::abs(pos - std::round(pos)) < 1e-9) {  // the vertex is on a beam
                const std::size_t on = static_cast<std::size_t>(std::round(pos));
                if (on == 0 || on + 1 >= n)
                    continue;
                below = on - 1;
                above = on + 1;
            }
            int hit = 0;
            const double t = castRay(edges, scene.discs, origin, yaw + bearing, maxRange, hit);
            if (t < range - 1e-6)
                continue;  // occluded
            const int lowerEdge = edgeOf[below], upperEdge = edgeOf[above];
            const bool bothWalls = (lowerEdge == edgeBefore && upperEdge == edgeAfter) ||
                                   (lowerEdge == edgeAfter && upperEdge == edgeBefore);
            if (!bothWalls)
                continue;
            // Arm lengths in beams, counting only while the wall is one continuous surface.
            unsigned lowerArm = 1, upperArm = 1;
            for (std::size_t k = below; k > 0 && edgeOf[k - 1] == lowerEdge && continuous(k - 1, k);
                 --k) {
                ++lowerArm;
            }
            for (std::size_t k = above;
                 k + 1 < n && edgeOf[k + 1] == upperEdge && continuous(k, k + 1); ++k) {
                ++upperArm;
            }

            GroundTruthCorner corner;
            corner.position = local;
            corner.range = range;
            const TPoint2D& prev = poly[(j + m - 1) % m];
            const TPoint2D& next = poly[(j + 1) % m];
            const double ax = prev.x - v.x, ay = prev.y - v.y, bx = next.x - v.x, by = next.y - v.y;
            corner.angle = std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by);
            // Walking the scan counter-clockwise: a left turn at the vertex is concave.
            const TPoint2D &a = hitPoint[below], &b = hitPoint[above];
            const double turn =
                (local.x - a.x) * (b.y - local.y) - (local.y - a.y) * (b.x - local.x);
            corner.type =
                turn > 0 ? features::EndpointType::Concave : features::EndpointType::Convex;
            corner.dontCare = lowerArm < options.minArmBeams || upperArm < options.minArmBeams;
            gt.corners.push_back(corner);
        }
    }

    gt.runs = wallRuns(edgeOf, hitPoint, scanIndex, options.minRunBeams);
    return gt;
}

}  // namespace toposlam::featureeval
