#include <toposlam/mapping/TrajectorySmoother.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>
#include <stdexcept>

namespace toposlam::mapping {

std::vector<mrpt::poses::CPose2D> smoothScanPositions(const std::vector<SmoothingInput>& scans) {
    std::vector<mrpt::poses::CPose2D> out;
    out.reserve(scans.size());
    for (const SmoothingInput& s : scans)
        out.push_back(s.pose);
    // Unknowns: the free scans' positions, x and y apart (the weights are the same for both).
    std::vector<long> unknown(scans.size(), -1);
    long n = 0;
    for (std::size_t i = 0; i < scans.size(); ++i) {
        if (!scans[i].fixed) {
            if (!(scans[i].poseVariance > 0))
                throw std::invalid_argument("smoothScanPositions: a free scan needs a variance");
            unknown[i] = n++;
        }
    }
    if (n == 0)
        return out;
    std::vector<Eigen::Triplet<double>> terms;
    terms.reserve(std::size_t(5 * n));
    Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(n, 2);
    for (std::size_t i = 0; i < scans.size(); ++i) {
        if (unknown[i] >= 0) {
            const double w = 1.0 / scans[i].poseVariance;
            terms.emplace_back(unknown[i], unknown[i], w);
            rhs.row(unknown[i]) += w * Eigen::RowVector2d(scans[i].pose.x(), scans[i].pose.y());
        }
        if (i == 0 || !scans[i].odometry)
            continue;
        if (!(scans[i].odometryVariance > 0))
            throw std::invalid_argument("smoothScanPositions: an odometry step needs a variance");
        const long a = unknown[i - 1], b = unknown[i];
        if (a < 0 && b < 0)
            continue;
        // Step from scan i-1 to scan i by odometry, in the world: p_i - p_{i-1} = step.
        const mrpt::poses::CPose2D& previous = scans[i - 1].pose;
        const double c = std::cos(previous.phi()), s = std::sin(previous.phi());
        const mrpt::poses::CPose2D& o = *scans[i].odometry;
        const Eigen::RowVector2d step(c * o.x() - s * o.y(), s * o.x() + c * o.y());
        const double w = 1.0 / scans[i].odometryVariance;
        if (b >= 0) {
            terms.emplace_back(b, b, w);
            rhs.row(b) += w * step;
        }
        if (a >= 0) {
            terms.emplace_back(a, a, w);
            rhs.row(a) -= w * step;
        }
        if (a >= 0 && b >= 0) {
            terms.emplace_back(a, b, -w);
            terms.emplace_back(b, a, -w);
        } else if (a >= 0) {  // scan i is fixed
            rhs.row(a) += w * Eigen::RowVector2d(scans[i].pose.x(), scans[i].pose.y());
        } else {  // scan i-1 is fixed
            rhs.row(b) += w * Eigen::RowVector2d(previous.x(), previous.y());
        }
    }
    Eigen::SparseMatrix<double> normal(n, n);
    normal.setFromTriplets(terms.begin(), terms.end());  // sums duplicates
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("smoothScanPositions: the normal equations did not factorise");
    const Eigen::MatrixX2d positions = solver.solve(rhs);
    for (std::size_t i = 0; i < scans.size(); ++i) {
        if (unknown[i] >= 0) {
            out[i] = mrpt::poses::CPose2D(positions(unknown[i], 0), positions(unknown[i], 1),
                                          scans[i].pose.phi());
        }
    }
    return out;
}

}  // namespace toposlam::mapping
