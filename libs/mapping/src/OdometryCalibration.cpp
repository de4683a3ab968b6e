#include <toposlam/mapping/OdometryCalibration.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace toposlam::mapping {

using mrpt::poses::CPose2D;

namespace {
/// Odometry steps shorter than this (m) say nothing about a scale (turning on the spot).
constexpr double kMinStep = 1e-3;
}  // namespace

double OdometryCalibration::estimate() const {
    if (odometrySquared_ <= 0)
        return 1.0;
    return std::clamp(motionDotOdometry_ / odometrySquared_, 1.0 - options_.maxCorrection,
                      1.0 + options_.maxCorrection);
}

double OdometryCalibration::scale() const {
    return options_.enabled && distance_ >= options_.minDistance ? estimate() : 1.0;
}

CPose2D OdometryCalibration::corrected(const CPose2D& increment) const {
    const double s = scale();
    return CPose2D(s * increment.x(), s * increment.y(), increment.phi());
}

void OdometryCalibration::observe(const CPose2D& odometry, const CPose2D& registered,
                                  const mrpt::math::CMatrixDouble33& covariance) {
    const double length = odometry.norm();
    if (length < kMinStep)  // gathered whether enabled or not: the summary reports it
        return;
    // Worst position variance: the larger eigenvalue of the 2x2 position block.
    const Eigen::Matrix2d position = covariance.asEigen().topLeftCorner<2, 2>();
    const double worstVariance =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(position, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .maxCoeff();
    if (!(worstVariance <= options_.maxStd * options_.maxStd))
        return;
    motionDotOdometry_ += registered.x() * odometry.x() + registered.y() * odometry.y();
    odometrySquared_ += length * length;
    distance_ += length;
}

}  // namespace toposlam::mapping
