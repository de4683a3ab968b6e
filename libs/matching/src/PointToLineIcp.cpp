#include <toposlam/matching/PointToLineIcp.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

void IcpOptions::declare(config::OptionsSchema& s) {
    s.integer("max_iterations", maxIterations, "", "Gauss-Newton iterations at most")
        .within(0, 10000);
    s.real("max_distance", maxDistance, "m", "points farther from their line are not used")
        .above(0);
    s.real("robust_scale", robustScale, "m", "Cauchy kernel scale").above(0);
    s.real("translation_tolerance", translationTolerance, "m", "stop below this step").atLeast(0);
    s.angle("rotation_tolerance", rotationTolerance, "... and this turn").atLeast(0);
    s.integer("stride", stride, "", "every stride-th beam").within(1, 1000);
    s.real("min_noise_std", minNoiseStd, "m", "floor of sigma in the covariance").atLeast(0);
    s.real("min_eigen_ratio", minEigenRatio, "",
           "steps only along directions the lines determine (eigenvalue / largest)")
        .within(0, 1);
}

/// Normal equations of one Gauss-Newton step.
struct PointToLineIcp::Accumulator {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    double weightedSq = 0, weightSum = 0;
    double leverSq = 0;  ///< weighted sum of the points' squared distances from the sensor
    std::size_t used = 0;

    /// Residual r = n . q - offset of the rotated point (rx, ry) + t = q.
    void add(double nx, double ny, double r, double rx, double ry, double c2) {
        const double w = 1.0 / (1.0 + r * r / c2);
        const Eigen::Vector3d J(nx, ny, -nx * ry + ny * rx);
        H.noalias() += w * J * J.transpose();
        g.noalias() += w * r * J;
        weightedSq += w * r * r;
        weightSum += w;
        leverSq += w * (rx * rx + ry * ry);
        ++used;
    }
    /// Applies the step to the pose; true when it was below the tolerances.
    bool step(double& x, double& y, double& phi, const IcpOptions& o) const {
        // Solve only along well-determined eigen-directions of H, with the turn measured by
        // how far it moves the points (lever = their RMS distance from the sensor). In radians
        // the turn's eigenvalue grows with the square of the range, and with far readings it
        // would make a translation the data do determine look undetermined next to it: that
        // translation would then never move from the start.
        const double lever = std::sqrt(leverSq / std::max(weightSum, 1e-12));
        const Eigen::Vector3d unit(1.0, 1.0, lever > 1e-6 ? 1.0 / lever : 1.0);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(unit.asDiagonal() * H *
                                                                 unit.asDiagonal());
        const Eigen::Vector3d scaledG = unit.cwiseProduct(g);
        const double largest = eig.eigenvalues().maxCoeff();
        Eigen::Vector3d d = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
            const double lambda = eig.eigenvalues()[k];
            if (!(lambda > o.minEigenRatio * largest) || !(lambda > 0))
                continue;
            const Eigen::Vector3d v = eig.eigenvectors().col(k);
            d -= (v.dot(scaledG) / lambda) * v;
        }
        d = unit.cwiseProduct(d);  // back to (m, m, rad)
        x += d[0], y += d[1], phi += d[2];
        return std::hypot(d[0], d[1]) < o.translationTolerance &&
               std::abs(d[2]) < o.rotationTolerance;
    }
};

namespace {
/// Smallest association gate of the second stage (m).
constexpr double kMinGate = 0.02;

/// Distance from p to the segment of node n, clamped at its ends.
double distanceToSegment(const SegmentNode& n, double px, double py) {
    const double t = std::clamp((px - n.start.x) * n.direction.x + (py - n.start.y) * n.direction.y,
                                0.0, n.length);
    return std::hypot(px - (n.start.x + t * n.direction.x), py - (n.start.y + t * n.direction.y));
}
}  // namespace

IcpResult PointToLineIcp::refine(const PolarScan& current, const AttributedGraph& currentGraph,
                                 const AttributedGraph& referenceGraph,
                                 const std::vector<SegmentMatch>& matches,
                                 const mrpt::poses::CPose2D& initial, const IcpOptions& options) {
    sorted_ = matches;
    std::sort(sorted_.begin(), sorted_.end(), [](const SegmentMatch& a, const SegmentMatch& b) {
        return a.current != b.current ? a.current < b.current : a.reference < b.reference;
    });

    IcpResult out;
    double x = initial.x(), y = initial.y(), phi = initial.phi();
    const std::uint32_t stride = std::uint32_t(std::max<std::size_t>(1, options.stride));
    const double c2 = options.robustScale * options.robustScale;
    Accumulator acc;
    for (int it = 0; it < options.maxIterations; ++it) {
        acc = Accumulator();
        const double c = std::cos(phi), s = std::sin(phi);
        for (std::size_t m = 0; m < sorted_.size();) {
            std::size_t end = m;
            while (end < sorted_.size() && sorted_[end].current == sorted_[m].current)
                ++end;
            const SegmentNode& cn = currentGraph.node(sorted_[m].current);
            for (std::uint32_t b = cn.firstBeam; b <= cn.lastBeam; b += stride) {
                if (b >= current.size() || !current.valid(b))
                    continue;
                const mrpt::math::TPoint2D& p = current.point(b);
                const double rx = c * p.x - s * p.y, ry = s * p.x + c * p.y;
                const double qx = rx + x, qy = ry + y;
                const SegmentNode* best = nullptr;
                double bestDist = std::numeric_limits<double>::infinity();
                for (std::size_t k = m; k < end; ++k) {
                    const SegmentNode& rn = referenceGraph.node(sorted_[k].reference);
                    const double d = distanceToSegment(rn, qx, qy);
                    if (d < bestDist)
                        bestDist = d, best = &rn;
                }
                const double r = best->normal.x * qx + best->normal.y * qy - best->offset;
                if (std::abs(r) > options.maxDistance)
                    continue;
                acc.add(best->normal.x, best->normal.y, r, rx, ry, c2);
            }
            m = end;
        }
        out.iterations = it + 1;
        if (acc.used < 3)
            break;
        if (acc.step(x, y, phi, options)) {
            out.converged = true;
            break;
        }
    }
    out.pose = mrpt::poses::CPose2D(x, y, phi);
    finish(out, acc, options);
    return out;
}

void PointToLineIcp::prepareReference(const PolarScan& reference, double maxJoinDistance) {
    const std::size_t n = reference.size();
    lines_.assign(n, std::nullopt);
    const double reach = localLineReach(surfaceNoise(reference, maxJoinDistance));
    for (std::size_t b = 0; b < n; ++b) {
        if (reference.valid(b))
            lines_[b] = fitLocalLine(reference, b, maxJoinDistance, reach);
    }
}

template <typename Correspond>
IcpResult PointToLineIcp::twoStageRefine(const PolarScan& current,
                                         const mrpt::poses::CPose2D& initial,
                                         const IcpOptions& options, double gate,
                                         Correspond&& correspond) const {
    IcpResult out;
    double x = initial.x(), y = initial.y(), phi = initial.phi();
    // Stage 1 (wide gate) on every stride-th point, stage 2 (tight gate) on all of them.
    std::size_t stride = std::max<std::size_t>(1, options.stride);
    const double c2 = options.robustScale * options.robustScale;
    const double widestGate = gate;
    bool tightened = false;
    Accumulator acc;
    for (int it = 0; it < options.maxIterations; ++it) {
        acc = Accumulator();
        const double c = std::cos(phi), s = std::sin(phi);
        const double gate2 = gate * gate;
        for (std::size_t i = 0; i < current.size(); i += stride) {
            if (!current.valid(i))
                continue;
            const mrpt::math::TPoint2D& p = current.point(i);
            const double rx = c * p.x - s * p.y, ry = s * p.x + c * p.y;
            double nx, ny, r;
            if (correspond(rx + x, ry + y, x, y, gate2, tightened, nx, ny, r))
                acc.add(nx, ny, r, rx, ry, c2);
        }
        out.iterations = it + 1;
        if (acc.used < 3)
            break;
        if (acc.step(x, y, phi, options)) {
            // Converged with the wide gate: once more with a gate of 3 sigma of the residuals
            // (at least kMinGate), which drops the points that only looked near a surface
            // (beside occluding edges, on moving people) and pulled the pose by millimetres.
            if (tightened) {
                out.converged = true;
                break;
            }
            tightened = true;
            const double sigma = std::sqrt(acc.weightedSq / std::max(1.0, acc.weightSum));
            gate = std::clamp(3 * sigma, kMinGate, widestGate);
            stride = 1;
        }
    }
    out.pose = mrpt::poses::CPose2D(x, y, phi);
    finish(out, acc, options);
    return out;
}

IcpResult PointToLineIcp::refineOnScan(const PolarScan& reference, const PolarScan& current,
                                       const mrpt::poses::CPose2D& initial,
                                       const IcpOptions& options, long searchBeams) {
    if (lines_.size() != reference.size())
        prepareReference(reference);  // never prepared
    // The local line of the nearest reference point among the beams around q's bearing.
    const auto correspond = [&](double qx, double qy, double sensorX, double sensorY, double gate2,
                                bool /*tight*/, double& nx, double& ny, double& r) {
        const long b = reference.beamAtPoint(qx, qy);
        if (b < 0)
            return false;
        long best = -1;
        double bestD2 = gate2;
        for (long o = -searchBeams; o <= searchBeams; ++o) {
            const long k = reference.neighbour(b, o);
            if (k < 0 || !lines_[std::size_t(k)])
                continue;
            const mrpt::math::TPoint2D& q = reference.point(std::size_t(k));
            const double d2 = (qx - q.x) * (qx - q.x) + (qy - q.y) * (qy - q.y);
            if (d2 < bestD2)
                bestD2 = d2, best = k;
        }
        if (best < 0)
            return false;
        const LocalLine& l = *lines_[std::size_t(best)];
        // The normal faces the reference sensor: the current one must be on that side too.
        if (l.nx * (sensorX - qx) + l.ny * (sensorY - qy) <= 0)
            return false;
        nx = l.nx, ny = l.ny, r = l.nx * qx + l.ny * qy - l.offset;
        return r * r <= gate2;
    };
    return twoStageRefine(current, initial, options, options.maxDistance, correspond);
}

IcpResult PointToLineIcp::refineOnMap(const LineMap& map, const PolarScan& current,
                                      const mrpt::poses::CPose2D& initial,
                                      const IcpOptions& options) {
    // The local line of the map point nearest to q (O(1) lookup), if the sensor can see that
    // surface from where it is and, in the wide-gate stage, the map point is confirmed.
    const std::uint32_t minViews = std::min(options.minMapViews, map.scans());
    const bool checkFacing = options.maxIncidence < M_PI;
    const double minFacing = std::cos(options.maxIncidence);
    const double minFacing2 = minFacing * std::abs(minFacing);
    const auto correspond = [&](double qx, double qy, double sensorX, double sensorY, double gate2,
                                bool tight, double& nx, double& ny, double& r) {
        const LineMapPoint* m = map.nearest(qx, qy);
        if (!m || (!tight && m->views < minViews) ||
            (!tight && options.skipMovedMapPoints && m->moved()))
            return false;
        // cos(incidence) = n . v / |v| with v towards the sensor, compared without a root.
        const double vx = sensorX - m->x, vy = sensorY - m->y;
        const double facing = m->nx * vx + m->ny * vy;
        if (facing <= 0 ||
            (checkFacing && facing * std::abs(facing) < minFacing2 * (vx * vx + vy * vy)))
            return false;  // the back of the surface, or seen too obliquely
        const double dx = qx - m->x, dy = qy - m->y;
        if (dx * dx + dy * dy > gate2)
            return false;
        nx = m->nx, ny = m->ny, r = m->nx * dx + m->ny * dy;
        return true;
    };
    return twoStageRefine(current, initial, options,
                          std::min(options.maxDistance, map.options().radius), correspond);
}

std::size_t PointToLineIcp::countOnMap(const LineMap& map, const PolarScan& current,
                                       const mrpt::poses::CPose2D& pose, double distance) {
    std::size_t on = 0;
    forEachReadingOnSurface(map, current, pose, distance, [&](const LineMapPoint&) { ++on; });
    return on;
}

void PointToLineIcp::finish(IcpResult& out, const Accumulator& acc,
                            const IcpOptions& options) const {
    out.pointsUsed = acc.used;
    out.residualRms = acc.weightSum > 0 ? std::sqrt(acc.weightedSq / acc.weightSum) : 0.0;
    // Covariance sigma^2 H^-1, with undetermined directions (tiny eigenvalues) set huge.
    const double dof = std::max(1.0, acc.weightSum - 3.0);
    const double sigma2 = std::max(acc.weightedSq / dof, options.minNoiseStd * options.minNoiseStd);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(acc.H);
    const double scale = std::max(1.0, eig.eigenvalues().maxCoeff());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 3; ++k) {
        const double lambda = eig.eigenvalues()[k];
        const double variance = lambda > 1e-9 * scale ? sigma2 / lambda : 1e6;
        cov += variance * eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose();
    }
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            out.covariance(r, k) = cov(r, k);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> te(cov.topLeftCorner<2, 2>());
    out.worstTranslationStd = std::sqrt(std::max(0.0, te.eigenvalues().maxCoeff()));
}

}  // namespace toposlam::matching
