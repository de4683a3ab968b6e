#include <toposlam/evaluation/RigidAlignment2D.h>

#include <cmath>
#include <stdexcept>

namespace toposlam::evaluation {

mrpt::math::TPose2D alignRigid2D(const std::vector<mrpt::math::TPoint2D>& source,
                                 const std::vector<mrpt::math::TPoint2D>& target) {
    if (source.size() != target.size()) {
        throw std::invalid_argument("alignRigid2D: point sets of different sizes");
    }
    if (source.empty())
        return {0, 0, 0};

    const double n = static_cast<double>(source.size());
    mrpt::math::TPoint2D sourceCentroid(0, 0), targetCentroid(0, 0);
    for (std::size_t i = 0; i < source.size(); ++i) {
        sourceCentroid += source[i];
        targetCentroid += target[i];
    }
    sourceCentroid *= 1.0 / n;
    targetCentroid *= 1.0 / n;

    // Σ a·b and Σ a×b over the centred pairs: the angle that maximises Σ (R a)·b.
    double dotSum = 0, crossSum = 0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const mrpt::math::TPoint2D a = source[i] - sourceCentroid;
        const mrpt::math::TPoint2D b = target[i] - targetCentroid;
        dotSum += a.x * b.x + a.y * b.y;
        crossSum += a.x * b.y - a.y * b.x;
    }
    const double theta = (dotSum == 0 && crossSum == 0) ? 0.0 : std::atan2(crossSum, dotSum);
    const double c = std::cos(theta), s = std::sin(theta);
    return {targetCentroid.x - (c * sourceCentroid.x - s * sourceCentroid.y),
            targetCentroid.y - (s * sourceCentroid.x + c * sourceCentroid.y), theta};
}

}  // namespace toposlam::evaluation
