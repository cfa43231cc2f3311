#include "pfdm/fit/residuals/analytic_point_residual.h"

#include <memory>
#include <random>

#include "gtest/gtest.h"
#include "pfdm/fit/residuals/point_residual.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

constexpr int kSizes[5] = {3, 4, kNumFunctions, kNumFunctions, kNumFunctions};

// Residuals and Jacobians of two cost functions on the same parameters.
void ExpectSame(const ceres::CostFunction& a, const ceres::CostFunction& b,
                double const* const* parameters) {
  const int n = a.num_residuals();
  ASSERT_EQ(n, b.num_residuals());
  std::vector<double> ra(n), rb(n);
  std::vector<std::vector<double>> ja(5), jb(5);
  double* pa[5];
  double* pb[5];
  for (int i = 0; i < 5; ++i) {
    ja[i].assign(n * kSizes[i], 0.0);
    jb[i].assign(n * kSizes[i], 0.0);
    pa[i] = ja[i].data();
    pb[i] = jb[i].data();
  }
  ASSERT_TRUE(a.Evaluate(parameters, ra.data(), pa));
  ASSERT_TRUE(b.Evaluate(parameters, rb.data(), pb));
  for (int r = 0; r < n; ++r) EXPECT_NEAR(ra[r], rb[r], 1e-12);
  for (int i = 0; i < 5; ++i) {
    for (size_t k = 0; k < ja[i].size(); ++k) {
      EXPECT_NEAR(ja[i][k], jb[i][k], 1e-10 * (1.0 + std::abs(jb[i][k])))
          << "block " << i << " entry " << k;
    }
  }
}

TEST(AnalyticPointResidualTest, MatchesAutodiffAtRandomStates) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Vector4d q(unit(random), unit(random), unit(random), unit(random));
    q.normalize();
    double center[3] = {10 * unit(random), 10 * unit(random),
                        10 * unit(random)};
    FunctionValues f[3];
    for (FunctionValues& values : f) {
      values = DefaultFunctionValues();
      values[kA0] = 50.0 + 10 * unit(random);
      for (int i : {kA1, kA2, kA3}) values[i] = 0.5 + 0.4 * unit(random);
      for (int i : {kEps1, kEps2}) values[i] = 1.0 + 0.5 * unit(random);
      for (int i : {kB0, kB2, kE1o, kE2o, kE3o}) values[i] = 3 * unit(random);
      for (int i : {kB1, kB3, kTau}) values[i] = unit(random);
    }
    const double u = 1.5 * unit(random), v = 3.1 * unit(random);
    const double weight = 0.5 + 0.5 * unit(random);
    const FunctionMask mask = random() & ((1u << kNumFunctions) - 1);
    const bool unit_exponents = trial % 5 == 0;
    const Eigen::Vector3d data(unit(random), unit(random), unit(random));
    const double* parameters[] = {center, q.data(), f[0].data(), f[1].data(),
                                  f[2].data()};
    std::unique_ptr<ceres::CostFunction> autodiff(
        PointResidual::Create(data, u, v, weight, mask, unit_exponents));
    AnalyticPointResidual analytic(PointSample(data, u, v, weight), mask,
                                   unit_exponents);
    ExpectSame(analytic, *autodiff, parameters);

    const Eigen::Vector3d normal = Eigen::Vector3d(1, 2, 2) / 3.0;
    std::unique_ptr<ceres::CostFunction> autodiff_surface(
        SurfaceResidual::Create(data, u, v, weight, mask, unit_exponents,
                                normal));
    AnalyticSurfaceResidual analytic_surface(
        PointSample(data, u, v, weight, normal), mask, unit_exponents);
    ExpectSame(analytic_surface, *autodiff_surface, parameters);
  }
}

TEST(AnalyticPointResidualTest, SkipsJacobiansCeresDoesNotAskFor) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 40.0;
  double center[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
  const double* parameters[] = {center, q, f.data(), f.data(), f.data()};
  AnalyticPointResidual cost(
      PointSample(Eigen::Vector3d::Zero(), 0.2, 0.3, 0.5),
      ModelConfig::Paper(17).FreeMask(), true);
  double residual[3], knot_jacobian[3 * kNumFunctions];
  double* jacobians[5] = {nullptr, nullptr, nullptr, knot_jacobian, nullptr};
  ASSERT_TRUE(cost.Evaluate(parameters, residual, jacobians));
  // d x / d a1 at the first knot: (1 - w) a0 cos u cos v along x.
  EXPECT_NEAR(knot_jacobian[kA1], 0.5 * 40.0 * std::cos(0.2) * std::cos(0.3),
              1e-12);
  EXPECT_EQ(knot_jacobian[kA0], 0.0);  // Held: comes from the globals.
}

}  // namespace
}  // namespace pfdm
