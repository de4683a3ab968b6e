// The pose graph's edge residual and optimisation against exact answers.
#include <ceres/ceres.h>
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/mapping/PoseGraph.h>
#include <toposlam/mapping/RelativePoseError.h>

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace {
using mrpt::poses::CPose2D;
using toposlam::mapping::EdgeKind;
using toposlam::mapping::PoseGraph;

Eigen::Matrix3d sqrtInformationOf(const Eigen::Matrix3d& covariance) {
    return Eigen::Matrix3d(covariance.inverse().llt().matrixU());
}

mrpt::math::CMatrixDouble33 diagonal(double sxy, double sphi) {
    mrpt::math::CMatrixDouble33 c;
    c.setZero();
    c(0, 0) = c(1, 1) = sxy * sxy;
    c(2, 2) = sphi * sphi;
    return c;
}
}  // namespace

TEST(RelativePoseError, AnalyticJacobiansMatchNumericDifferentiation) {
    Eigen::Matrix3d covariance;
    covariance << 0.01, 0.002, 0.001,  //
        0.002, 0.02, -0.001,           //
        0.001, -0.001, 0.005;
    const std::unique_ptr<ceres::CostFunction> cost(toposlam::mapping::makeRelativePoseError(
        CPose2D(1.2, -0.4, 0.7), sqrtInformationOf(covariance)));
    // Central differences by hand: ceres::GradientChecker hands Eigen matrices across the
    // library boundary, which breaks when Ceres and this test align Eigen differently (ASan).
    const double h = 1e-6;
    // Headings on both sides of +-pi (the residual wraps) and well away from it.
    const std::vector<std::array<double, 6>> cases = {{0.3, -1.0, 0.2, 1.5, -1.1, 0.95},
                                                      {-2.0, 4.0, 3.0, -1.0, 3.5, -2.9},
                                                      {10.0, 5.0, -1.4, 10.5, 6.0, -0.6}};
    for (const auto& c : cases) {
        std::array<double, 6> x = c;
        const double* parameters[2] = {x.data(), x.data() + 3};
        double residual[3], ja[9], jb[9];
        double* jacobians[2] = {ja, jb};
        ASSERT_TRUE(cost->Evaluate(parameters, residual, jacobians));
        for (int k = 0; k < 6; ++k) {
            double plus[3], minus[3];
            x[std::size_t(k)] = c[std::size_t(k)] + h;
            ASSERT_TRUE(cost->Evaluate(parameters, plus, nullptr));
            x[std::size_t(k)] = c[std::size_t(k)] - h;
            ASSERT_TRUE(cost->Evaluate(parameters, minus, nullptr));
            x[std::size_t(k)] = c[std::size_t(k)];
            const double* analytic = k < 3 ? ja : jb;  // row-major 3 x 3 per block
            for (int r = 0; r < 3; ++r) {
                const double numeric = (plus[r] - minus[r]) / (2 * h);
                EXPECT_NEAR(analytic[r * 3 + k % 3], numeric, 1e-5 * (1 + std::abs(numeric)))
                    << "residual " << r << ", parameter " << k;
            }
        }
    }
}

TEST(RelativePoseError, ResidualIsZeroAtTheMeasurementAndWhitened) {
    const CPose2D z(0.5, 0.25, 3.0);  // heading near +pi: b's heading wraps past it
    const std::unique_ptr<ceres::CostFunction> cost(toposlam::mapping::makeRelativePoseError(
        z, sqrtInformationOf(Eigen::Vector3d(0.01, 0.01, 0.0025).asDiagonal())));
    const CPose2D a(2, 1, 0.8);
    const CPose2D b = a + z;
    double pa[3] = {a.x(), a.y(), a.phi()}, pb[3] = {b.x(), b.y(), b.phi()};
    const double* parameters[2] = {pa, pb};
    double r[3];
    ASSERT_TRUE(cost->Evaluate(parameters, r, nullptr));
    EXPECT_NEAR(r[0], 0, 1e-12);
    EXPECT_NEAR(r[1], 0, 1e-12);
    EXPECT_NEAR(r[2], 0, 1e-12);
    pb[2] += 0.1;  // 0.1 rad off with sigma 0.05 rad: two standard deviations
    ASSERT_TRUE(cost->Evaluate(parameters, r, nullptr));
    EXPECT_NEAR(r[2], 2.0, 1e-9);
}

TEST(PoseGraph, LoopEdgeRemovesTheDriftOfASquare) {
    // A 4 m square driven in 1 m steps; odometry turns 1 degree too much per corner, then a
    // loop edge says the last node is where the first was. The optimum spreads the error.
    std::vector<CPose2D> truth;
    for (int side = 0; side < 4; ++side)
        for (int step = 0; step < 4; ++step) {
            const double phi = mrpt::math::wrapToPi(side * M_PI / 2);
            const CPose2D corner = side == 0   ? CPose2D(0, 0, 0)
                                   : side == 1 ? CPose2D(4, 0, 0)
                                   : side == 2 ? CPose2D(4, 4, 0)
                                               : CPose2D(0, 4, 0);
            truth.push_back(
                CPose2D(corner.x() + step * std::cos(phi), corner.y() + step * std::sin(phi), phi));
        }
    truth.push_back(truth.front());  // back at the start
    PoseGraph graph(0);
    CPose2D drifted = truth[0];
    graph.addNode(drifted);
    const double bias = 1.0 * M_PI / 180;
    for (std::size_t i = 1; i < truth.size(); ++i) {
        const CPose2D step = truth[i] - truth[i - 1];
        const CPose2D measured(step.x(), step.y(), step.phi() + (i % 4 == 0 ? bias : 0));
        drifted = drifted + measured;
        graph.addNode(drifted);
        graph.addEdge(i - 1, i, measured, diagonal(0.01, 0.01), EdgeKind::Odometry);
    }
    const double driftBefore = (graph.pose(truth.size() - 1) - truth.back()).norm();
    ASSERT_GT(driftBefore, 0.1);
    graph.addEdge(0, truth.size() - 1, CPose2D(), diagonal(0.001, 0.001), EdgeKind::Loop);
    graph.optimize(50);
    // Each corner's 1 degree bias is spread over the cycle: no node is off by more than
    // the bias times the longest lever (4 m) from the truth, and the loop closes.
    EXPECT_LT((graph.pose(truth.size() - 1) - graph.pose(0)).norm(), 0.01);
    for (std::size_t i = 0; i < truth.size(); ++i)
        EXPECT_LT((graph.pose(i) - truth[i]).norm(), 4 * 4 * bias) << "node " << i;
    EXPECT_LT(graph.totalChi2(), driftBefore * driftBefore / (0.001 * 0.001));
}

TEST(PoseGraph, LoopsWithoutTheRobustLossPullFromManySigmaOff) {
    // Nine 1 m steps with stiff edges (1 cm) and four loop edges (3 cm) that all put the last
    // node 0.5 m farther: 17 sigma each. Under the Cauchy loss they pull it by 7 cm only (their
    // weight falls with the residual); without it the last node goes to the least-squares optimum,
    // 0.5 * (4 / 0.03^2) / (4 / 0.03^2 + 1 / (9 * 0.01^2)) = 0.4 m farther.
    const auto lastNodeAfterOptimising = [](bool robust) {
        PoseGraph graph(3.0);
        graph.addNode(CPose2D());
        for (std::size_t i = 1; i <= 9; ++i) {
            graph.addNode(CPose2D(double(i), 0, 0));
            graph.addEdge(i - 1, i, CPose2D(1, 0, 0), diagonal(0.01, 0.001), EdgeKind::Odometry);
        }
        for (int k = 0; k < 4; ++k)
            graph.addEdge(0, 9, CPose2D(9.5, 0, 0), diagonal(0.03, 0.01), EdgeKind::Loop, robust);
        graph.optimize(50);
        return graph.pose(9).x();
    };
    EXPECT_LT(lastNodeAfterOptimising(true) - 9.0, 0.1);
    EXPECT_NEAR(lastNodeAfterOptimising(false), 9.4, 0.001);
}
