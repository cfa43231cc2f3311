#include "pfdm/analytic_point_residual.h"

#include <memory>
#include <random>

#include "gtest/gtest.h"
#include "pfdm/model.h"
#include "pfdm/point_residual.h"
#include "pfdm/square_root_form.h"

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

namespace pfdm {
namespace {

// A group over compact knot blocks against its points one by one: the
// square-root form must give the stacked rows' cost, gradient and J^T J.
TEST(PointGroupResidualTest,
     SquareRootFormKeepsTheStackedPointsNormalEquations) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const ModelConfig config = ModelConfig::Paper(17);
  const FunctionMask mask = config.FreeMask();
  FunctionValues globals = DefaultFunctionValues(), knot0, knot1;
  globals[kA0] = 60.0;
  knot0 = knot1 = globals;
  knot0[kA1] = 0.4, knot1[kA1] = 0.45, knot0[kB0] = 2.0, knot1[kTau] = 0.1;
  std::vector<int> free;
  for (int f = 0; f < kNumFunctions; ++f) {
    if ((mask >> f) & 1u) free.push_back(f);
  }
  FreeEntries entries0(knot0.data(), free), entries1(knot1.data(), free);
  double center[3] = {1, 2, 3};
  double quaternion[4] = {1, 0, 0, 0};

  std::vector<PointSample> samples;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d data(30 * unit(random), 30 * unit(random),
                               30 * unit(random));
    const double u = 1.2 * unit(random), v = 3.1 * unit(random);
    const double w = 0.5 + 0.5 * unit(random);
    samples.push_back(
        i % 4 == 0 ? PointSample(data, u, v, w, Eigen::Vector3d(0, 0.6, 0.8))
                   : PointSample(data, u, v, w));
  }
  const PointGroupResidual group(samples, mask, true,
                                 {nullptr, &entries0, &entries1},
                                 {false, false, false, true, true});
  ASSERT_TRUE(group.compressed());
  const int n = 2 * static_cast<int>(free.size());
  ASSERT_EQ(group.num_residuals(), n + 1);

  // The stacked rows, from the per-point residual on whole blocks.
  int rows = 0;
  for (const PointSample& sample : samples) rows += sample.num_residuals();
  Eigen::MatrixXd j(rows, n);
  Eigen::VectorXd r(rows);
  int row = 0;
  const double* whole[] = {center, quaternion, globals.data(), knot0.data(),
                           knot1.data()};
  for (const PointSample& sample : samples) {
    const int m = sample.num_residuals();
    std::vector<double> residual(m), jacobian0(m * kNumFunctions),
        jacobian1(m * kNumFunctions);
    double* jacobians[] = {nullptr, nullptr, nullptr, jacobian0.data(),
                           jacobian1.data()};
    EvaluatePointSample(sample, mask, true, whole, residual.data(), jacobians);
    for (int i = 0; i < m; ++i) {
      r[row + i] = residual[i];
      for (size_t c = 0; c < free.size(); ++c) {
        j(row + i, c) = jacobian0[i * kNumFunctions + free[c]];
        j(row + i, free.size() + c) = jacobian1[i * kNumFunctions + free[c]];
      }
    }
    row += m;
  }

  const double* compact[] = {center, quaternion, globals.data(),
                             entries0.parameters(), entries1.parameters()};
  std::vector<double> z(n + 1);
  ASSERT_TRUE(group.Evaluate(compact, z.data(), nullptr));
  EXPECT_NEAR(z[0], r.norm(), 1e-12 * r.norm());
  for (int i = 1; i <= n; ++i) EXPECT_EQ(z[i], 0.0);

  const int width = static_cast<int>(free.size());
  RowMajorMatrix jacobian0((n + 1), width), jacobian1((n + 1), width);
  double* jacobians[] = {nullptr, nullptr, nullptr, jacobian0.data(),
                         jacobian1.data()};
  ASSERT_TRUE(group.Evaluate(compact, z.data(), jacobians));
  Eigen::MatrixXd jc(n + 1, n);
  jc << jacobian0, jacobian1;
  const Eigen::VectorXd rc = Eigen::Map<Eigen::VectorXd>(z.data(), n + 1);
  const double scale = j.squaredNorm();
  EXPECT_LT((jc.transpose() * jc - j.transpose() * j).norm(), 1e-11 * scale);
  EXPECT_LT((jc.transpose() * rc - j.transpose() * r).norm(),
            1e-11 * std::sqrt(scale) * r.norm());
  EXPECT_NEAR(rc.squaredNorm(), r.squaredNorm(), 1e-11 * r.squaredNorm());
}

// Too few rows to gain from the square-root form: the rows themselves.
TEST(PointGroupResidualTest, SmallGroupsGiveTheirRows) {
  const FunctionMask mask = ModelConfig::Paper(17).FreeMask();
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  double center[3] = {1, 2, 3};
  double quaternion[4] = {1, 0, 0, 0};
  const PointSample sample(Eigen::Vector3d(10, 20, 5), 0.3, 1.1, 0.4);
  const PointGroupResidual group({sample, sample}, mask, true);
  EXPECT_FALSE(group.compressed());
  AnalyticPointResidual single(sample, mask, true);
  const double* parameters[] = {center, quaternion, f.data(), f.data(),
                                f.data()};
  double grouped[6], alone[3];
  ASSERT_TRUE(group.Evaluate(parameters, grouped, nullptr));
  ASSERT_TRUE(single.Evaluate(parameters, alone, nullptr));
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(grouped[i], alone[i]);
    EXPECT_EQ(grouped[3 + i], alone[i]);
  }
}

}  // namespace
}  // namespace pfdm
