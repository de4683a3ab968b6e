#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/evaluation/SensorMounting.h>
#include <toposlam/evaluation/StampedPoseLookup.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

namespace toposlam::evaluation {

namespace {

using mrpt::math::TPose2D;

/// b in a's frame: a^-1 (+) b.
TPose2D relative(const TPose2D& a, const TPose2D& b) {
    return (mrpt::poses::CPose2D(b) - mrpt::poses::CPose2D(a)).asTPose();
}

/// The two translation equations of one pair (robot motion a, sensor motion b): rows of the
/// system M [t_x t_y s·cos s·sin]' = r.
struct PairEquations {
    Eigen::Matrix<double, 2, 4> m;
    Eigen::Vector2d r;
};

PairEquations equations(const TPose2D& a, const TPose2D& b) {
    const double c = std::cos(a.phi), s = std::sin(a.phi);
    PairEquations e;
    e.m << c - 1, -s, -b.x, b.y,  //
        s, c - 1, -b.y, -b.x;
    e.r << -a.x, -a.y;
    return e;
}

struct Solution {
    Eigen::Vector4d x;
    Eigen::Matrix4d normalInverse;
    double residualRms = 0;
};

std::optional<Solution> solve(const std::vector<PairEquations>& pairs,
                              const std::vector<bool>& use) {
    Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    std::size_t n = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (!use[i])
            continue;
        normal += pairs[i].m.transpose() * pairs[i].m;
        rhs += pairs[i].m.transpose() * pairs[i].r;
        ++n;
    }
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(normal);
    if (n == 0 || !lu.isInvertible())
        return std::nullopt;
    Solution out;
    out.x = lu.solve(rhs);
    out.normalInverse = lu.inverse();
    double sq = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i)
        if (use[i])
            sq += (pairs[i].m * out.x - pairs[i].r).squaredNorm();
    out.residualRms = std::sqrt(sq / double(2 * n));
    return out;
}

}  // namespace

std::optional<SensorMounting> estimateSensorMounting(const io::Trajectory2D& odometry,
                                                     const io::Trajectory2D& sensorPoses,
                                                     double stampTolerance,
                                                     const SensorMountingOptions& options) {
    // The trajectory's poses that have an odometry reading, in the trajectory's order.
    const StampedPoseLookup lookup(odometry, stampTolerance);
    std::vector<std::pair<TPose2D, TPose2D>> matched;  // (odometry, sensor)
    for (const io::TimedPose2D& p : sensorPoses)
        if (const auto k = lookup.find(p.stamp))
            matched.push_back({odometry[*k].pose, p.pose});

    std::vector<PairEquations> pairs;
    const std::size_t step = std::max<std::size_t>(1, options.pairStep);
    for (std::size_t i = 0; i + step < matched.size(); ++i) {
        const TPose2D a = relative(matched[i].first, matched[i + step].first);
        const TPose2D b = relative(matched[i].second, matched[i + step].second);
        if (std::abs(a.phi) < options.minTurn || std::hypot(a.x, a.y) > options.maxMotion ||
            std::abs(mrpt::math::wrapToPi(a.phi - b.phi)) > options.maxTurnDisagreement)
            continue;
        pairs.push_back(equations(a, b));
    }
    constexpr std::size_t kMinPairs = 10;
    if (pairs.size() < kMinPairs)
        return std::nullopt;

    std::vector<bool> use(pairs.size(), true);
    auto first = solve(pairs, use);
    if (!first)
        return std::nullopt;
    // Wheel slip within a pair: its equations miss by far more than the rest.
    const double bound = 3 * first->residualRms;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const Eigen::Vector2d e = pairs[i].m * first->x - pairs[i].r;
        use[i] = std::abs(e(0)) <= bound && std::abs(e(1)) <= bound;
        kept += use[i];
    }
    const auto final = kept >= kMinPairs ? solve(pairs, use) : first;
    if (!final)
        return std::nullopt;

    SensorMounting out;
    const Eigen::Vector4d& x = final->x;
    // The system is in the odometry's units: with odometry distances s times the trajectory's,
    // every term carries s, the mounting's translation too.
    out.odometryScale = std::hypot(x(2), x(3));
    out.mounting = {x(0) / out.odometryScale, x(1) / out.odometryScale, std::atan2(x(3), x(2))};
    out.pairs = kept >= kMinPairs ? kept : pairs.size();
    out.residualRms = final->residualRms;
    // Pairs overlap (each pose is in 2 pairStep of them), so their errors are not independent:
    // the plain least-squares deviation would be about sqrt(pairStep) too small.
    const double variance = final->residualRms * final->residualRms * double(step);
    out.stdX = std::sqrt(variance * final->normalInverse(0, 0)) / out.odometryScale;
    out.stdY = std::sqrt(variance * final->normalInverse(1, 1)) / out.odometryScale;
    return out;
}

}  // namespace toposlam::evaluation
