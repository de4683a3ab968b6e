#include <ceres/sized_cost_function.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/mapping/RelativePoseError.h>

#include <cmath>

namespace toposlam::mapping {

namespace {
class RelativePoseError final : public ceres::SizedCostFunction<3, 3, 3> {
  public:
    RelativePoseError(const mrpt::poses::CPose2D& z, const Eigen::Matrix3d& sqrtInformation)
        : x_(z.x()), y_(z.y()), phi_(z.phi()), sqrtInformation_(sqrtInformation) {}

    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        const double* a = parameters[0];
        const double* b = parameters[1];
        const double c = std::cos(a[2]), s = std::sin(a[2]);
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double d = b[2] - a[2] - phi_;
        const Eigen::Vector3d e(c * dx + s * dy - x_, -s * dx + c * dy - y_,
                                mrpt::math::wrapToPi(d));
        Eigen::Map<Eigen::Vector3d> r(residuals);
        r = sqrtInformation_ * e;
        if (!jacobians)
            return true;
        if (jacobians[0]) {  // d e / d (ax, ay, aphi)
            Eigen::Matrix3d j;
            j << -c, -s, -s * dx + c * dy,  //
                s, -c, -c * dx - s * dy,    //
                0, 0, -1;
            Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> ja(jacobians[0]);
            ja = sqrtInformation_ * j;
        }
        if (jacobians[1]) {  // d e / d (bx, by, bphi)
            Eigen::Matrix3d j;
            j << c, s, 0,  //
                -s, c, 0,  //
                0, 0, 1;
            Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jb(jacobians[1]);
            jb = sqrtInformation_ * j;
        }
        return true;
    }

  private:
    double x_, y_, phi_;
    Eigen::Matrix3d sqrtInformation_;
};

}  // namespace

ceres::CostFunction* makeRelativePoseError(const mrpt::poses::CPose2D& measurement,
                                           const Eigen::Matrix3d& sqrtInformation) {
    return new RelativePoseError(measurement, sqrtInformation);
}

}  // namespace toposlam::mapping
