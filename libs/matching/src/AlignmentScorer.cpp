#include <toposlam/matching/AlignmentScorer.h>
#include <toposlam/matching/LocalLine.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

void AlignmentScoreOptions::declare(config::OptionsSchema& s) {
    s.real("inlier_distance", inlierDistance, "m",
           "a point this near the other surface is an inlier")
        .above(0);
    s.integer("search_beams", searchBeams, "", "reference beams looked at each side of the bearing")
        .within(0, 1000);
    s.integer("stride", stride, "", "score every stride-th current beam").within(1, 1000);
    s.real("max_join_distance", maxJoinDistance, "m",
           "neighbouring reference points farther apart (+ 3 beam arcs) are not joined")
        .atLeast(0);
}

double AlignmentScore::inlierRms() const {
    return inliers > 0 ? std::sqrt(inlierSquaredError / double(inliers)) : 0.0;
}

namespace {
double squaredDistanceToSegment(double px, double py, const mrpt::math::TPoint2D& a,
                                const mrpt::math::TPoint2D& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - a.x) * dx + (py - a.y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = px - (a.x + t * dx), ey = py - (a.y + t * dy);
    return ex * ex + ey * ey;
}
/// True when the points u and v lie on opposite sides of the line through a and b.
bool oppositeSides(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, double ux,
                   double uy, double vx, double vy) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return (dx * (uy - a.y) - dy * (ux - a.x)) * (dx * (vy - a.y) - dy * (vx - a.x)) < 0;
}
/// True when the reference saw farther than `range` (+ margin) on beam b and on both its
/// neighbours: a point there contradicts the reference. Requiring the neighbours too keeps
/// a beam that just grazes past an edge from calling the edge's points violations.
bool inFreeSpace(const PolarScan& reference, long b, double range, double margin) {
    for (long o = -1; o <= 1; ++o) {
        const long r = reference.neighbour(b, o);
        if (r < 0)
            continue;
        if (!reference.valid(std::size_t(r)) || range >= reference.range(std::size_t(r)) - margin)
            return false;
    }
    return true;
}
}  // namespace

AlignmentScore scoreAlignment(const PolarScan& reference, const PolarScan& current,
                              const mrpt::poses::CPose2D& pose,
                              const AlignmentScoreOptions& options) {
    AlignmentScore s;
    const double c = std::cos(pose.phi()), sn = std::sin(pose.phi());
    const double tol2 = options.inlierDistance * options.inlierDistance;
    const std::size_t stride = std::max<std::size_t>(1, options.stride);

    for (std::size_t i = 0; i < current.size(); i += stride) {
        if (!current.valid(i))
            continue;
        const mrpt::math::TPoint2D& p = current.point(i);
        const double qx = pose.x() + c * p.x - sn * p.y, qy = pose.y() + sn * p.x + c * p.y;
        const long b = reference.beamAtPoint(qx, qy);
        if (b < 0) {
            ++s.unverifiable;
            ++s.outOfView;
            continue;
        }
        double best = std::numeric_limits<double>::infinity();
        bool fromBehind = false;  // the nearest piece of surface faces away from the sensor
        long prev = -1;
        for (long o = -options.searchBeams; o <= options.searchBeams; ++o) {
            const long r = reference.neighbour(b, o);
            if (r < 0 || !reference.valid(std::size_t(r))) {
                prev = -1;
                continue;
            }
            const mrpt::math::TPoint2D& q = reference.point(std::size_t(r));
            const double toPoint = (qx - q.x) * (qx - q.x) + (qy - q.y) * (qy - q.y);
            if (toPoint < best)
                best = toPoint, fromBehind = false;
            if (prev >= 0) {
                const mrpt::math::TPoint2D& pq = reference.point(std::size_t(prev));
                const double join =
                    jumpGap(reference, reference.range(std::size_t(r)), options.maxJoinDistance);
                if ((pq.x - q.x) * (pq.x - q.x) + (pq.y - q.y) * (pq.y - q.y) < join * join) {
                    const double toPiece = squaredDistanceToSegment(qx, qy, pq, q);
                    if (toPiece < best) {
                        best = toPiece;
                        // The reference sensor is at the origin; the current one at the pose.
                        fromBehind = oppositeSides(pq, q, 0, 0, pose.x(), pose.y());
                    }
                }
            }
            prev = r;
        }
        if (best <= tol2 && !fromBehind) {
            ++s.inliers;
            s.inlierSquaredError += best;
        } else if (inFreeSpace(reference, b, std::sqrt(qx * qx + qy * qy),
                               options.inlierDistance)) {
            ++s.violations;
        } else {
            ++s.unverifiable;
        }
    }
    return s;
}

}  // namespace toposlam::matching
