#include <toposlam/matching/PointToLineIcp.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toposlam::matching {

namespace {
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
    const std::size_t stride = std::max<std::size_t>(1, options.stride);
    const double c2 = options.robustScale * options.robustScale;
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    double weightedSq = 0, weightSum = 0;

    for (int it = 0; it < options.maxIterations; ++it) {
        H.setZero();
        Eigen::Vector3d g = Eigen::Vector3d::Zero();
        weightedSq = weightSum = 0;
        out.pointsUsed = 0;
        const double c = std::cos(phi), s = std::sin(phi);

        for (std::size_t m = 0; m < sorted_.size();) {
            std::size_t end = m;
            while (end < sorted_.size() && sorted_[end].current == sorted_[m].current)
                ++end;
            const SegmentNode& cn = currentGraph.node(sorted_[m].current);
            for (std::uint32_t b = cn.firstBeam; b <= cn.lastBeam; b += std::uint32_t(stride)) {
                if (b >= current.size() || !current.valid(b))
                    continue;
                const mrpt::math::TPoint2D& p = current.point(b);
                const double rx = c * p.x - s * p.y, ry = s * p.x + c * p.y;
                const double qx = rx + x, qy = ry + y;
                // Nearest candidate reference segment.
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
                const double w = 1.0 / (1.0 + r * r / c2);
                const Eigen::Vector3d J(best->normal.x, best->normal.y,
                                        best->normal.x * -ry + best->normal.y * rx);
                H.noalias() += w * J * J.transpose();
                g.noalias() += w * r * J;
                weightedSq += w * r * r;
                weightSum += w;
                ++out.pointsUsed;
            }
            m = end;
        }
        out.iterations = it + 1;
        if (out.pointsUsed < 3)
            break;
        // Levenberg damping keeps the step finite along undetermined directions.
        const Eigen::Vector3d step =
            -(H + 1e-9 * (1.0 + H.trace()) * Eigen::Matrix3d::Identity()).ldlt().solve(g);
        x += step[0], y += step[1], phi += step[2];
        if (std::hypot(step[0], step[1]) < options.translationTolerance &&
            std::abs(step[2]) < options.rotationTolerance) {
            out.converged = true;
            break;
        }
    }

    out.pose = mrpt::poses::CPose2D(x, y, phi);
    out.residualRms = weightSum > 0 ? std::sqrt(weightedSq / weightSum) : 0.0;
    // Covariance sigma^2 H^-1, with undetermined directions (tiny eigenvalues) set huge.
    const double dof = std::max(1.0, weightSum - 3.0);
    const double sigma2 = std::max(weightedSq / dof, options.minNoiseStd * options.minNoiseStd);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(H);
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
    return out;
}

}  // namespace toposlam::matching
