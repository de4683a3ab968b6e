#pragma once
// The residual of one pose-graph edge for Ceres: the measured pose z of node b in node a's
// frame against the estimate's, a^-1 (+) b, as (x, y, phi) with phi wrapped to (-pi, pi],
// whitened by the square root of the measurement's information matrix (upper Cholesky factor,
// so its squared norm is the edge's chi-square). Parameter blocks: a and b as (x, y, phi) in
// the world frame (m, rad). Analytic Jacobians: evaluating edges is most of what optimising a
// 2D pose graph costs.
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace toposlam::mapping {

/// A new cost function (the caller, usually a ceres::Problem, owns it).
ceres::CostFunction* makeRelativePoseError(const mrpt::poses::CPose2D& measurement,
                                           const Eigen::Matrix3d& sqrtInformation);

}  // namespace toposlam::mapping
