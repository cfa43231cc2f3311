#include "pfdm/fit/residuals/regularizer.h"

#include <memory>
#include <vector>

#include "ceres/autodiff_cost_function.h"
#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/model/model.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A unit of each function in millimetres of model-point motion, on a
// shell of a0 = 60 and ring radius 30 mm: the radii's and tau's at a0, the
// exponents' and bends' shapes at the ring's radius, the wall's fixed; a
// held function none.
TEST(RegularizerScalesTest, ConvertEachFunctionToMillimetres) {
  const Model shell = TestShell(9);
  const FunctionValues scales = RegularizerScales(shell, {kB0, kE3o});
  EXPECT_DOUBLE_EQ(scales[kA0], 1.0);
  EXPECT_DOUBLE_EQ(scales[kA1], 60.0);
  EXPECT_DOUBLE_EQ(scales[kA3], 60.0);
  EXPECT_DOUBLE_EQ(scales[kEps1], 30.0);
  EXPECT_DOUBLE_EQ(scales[kB1], 30.0);
  EXPECT_DOUBLE_EQ(scales[kTau], 60.0);
  EXPECT_DOUBLE_EQ(scales[kDtau], 30.0);
  EXPECT_DOUBLE_EQ(scales[kH], 0.5);
  EXPECT_DOUBLE_EQ(scales[kE1o], 1.0);
  EXPECT_EQ(scales[kB0], 0.0);
  EXPECT_EQ(scales[kE3o], 0.0);
}

TEST(SmoothnessResidualTest, LinearTrendsCostNothingAndBendsDo) {
  FunctionValues scales{};
  scales[kA1] = 10.0;
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessResidual::Create(2.0, scales));
  FunctionValues a{}, b{}, c{};
  a[kA1] = 0.1, b[kA1] = 0.2, c[kA1] = 0.3;
  a[kA2] = 5.0;  // Scale 0: ignored.
  const double* parameters[] = {a.data(), b.data(), c.data()};
  double residuals[kNumFunctions];
  ASSERT_TRUE(cost->Evaluate(parameters, residuals, nullptr));
  for (double r : residuals) EXPECT_NEAR(r, 0.0, 1e-12);
  c[kA1] = 0.5;
  ASSERT_TRUE(cost->Evaluate(parameters, residuals, nullptr));
  EXPECT_NEAR(residuals[kA1], 2.0 * 10.0 * 0.2, 1e-12);
}

TEST(PriorResidualTest, PullsTowardThePrior) {
  FunctionValues scales{}, prior{}, values{};
  scales[kTau] = 30.0;
  prior[kTau] = 0.1;
  values[kTau] = 0.15;
  std::unique_ptr<ceres::CostFunction> cost(
      PriorResidual::Create(0.5, scales, prior));
  const double* parameters[] = {values.data()};
  double residuals[kNumFunctions];
  ASSERT_TRUE(cost->Evaluate(parameters, residuals, nullptr));
  EXPECT_NEAR(residuals[kTau], 0.5 * 30.0 * 0.05, 1e-12);
  EXPECT_EQ(residuals[kA1], 0.0);
}

TEST(AxisGaugeResidualTest, VanishesForCentresScatteredAboutAStraightAxis) {
  const int num_knots = 5;
  std::vector<FunctionValues> knots(num_knots, FunctionValues{});
  // Zero mean, zero linear trend: a symmetric bow.
  const double bow[num_knots] = {1.0, -0.5, -1.0, -0.5, 1.0};
  std::vector<const double*> parameters;
  for (int k = 0; k < num_knots; ++k) {
    knots[k][kE1o] = bow[k];
    knots[k][kE2o] = -bow[k];
    parameters.push_back(knots[k].data());
  }
  AxisGaugeResidual gauge(num_knots, 3.0);
  double residuals[4];
  ASSERT_TRUE(gauge.Evaluate(parameters.data(), residuals, nullptr));
  for (double r : residuals) EXPECT_NEAR(r, 0.0, 1e-12);
  // A shift and a tilt of the axis are what it measures.
  for (int k = 0; k < num_knots; ++k) knots[k][kE1o] = 2.0 + 0.5 * k;
  ASSERT_TRUE(gauge.Evaluate(parameters.data(), residuals, nullptr));
  EXPECT_NEAR(residuals[0], 3.0 * (2.0 + 0.5 * 2.0), 1e-12);
  EXPECT_NEAR(residuals[2], 3.0 * 0.5 * (4 + 1 + 0 + 1 + 4) / num_knots, 1e-12);
}

TEST(AxisGaugeResidualTest, JacobianMatchesNumericDifferences) {
  const int num_knots = 4;
  std::vector<FunctionValues> knots(num_knots, DefaultFunctionValues());
  std::vector<const double*> parameters;
  for (int k = 0; k < num_knots; ++k) {
    knots[k][kE1o] = 0.3 * k;
    parameters.push_back(knots[k].data());
  }
  AxisGaugeResidual gauge(num_knots, 2.0);
  ceres::NumericDiffOptions options;
  const std::vector<const ceres::Manifold*> manifolds(num_knots, nullptr);
  ceres::GradientChecker checker(&gauge, &manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters.data(), 1e-9, &results))
      << results.error_log;
}

// SmoothnessResidual as it was, for autodiff (sqrt(w) = 1.7).
struct TemplatedSmoothness {
  template <typename T>
  bool operator()(const T* p, const T* k, const T* n, T* r) const {
    for (int f = 0; f < kNumFunctions; ++f) {
      r[f] = 1.7 * scales[f] * (p[f] - 2.0 * k[f] + n[f]);
    }
    return true;
  }
  FunctionValues scales;
};

// The written-out Jacobians against numeric differences, every function
// scaled (one by 0, as a held function is), and bit for bit the values
// ceres::AutoDiffCostFunction took from the templated residuals before.
TEST(SmoothnessResidualTest, JacobiansMatchNumericAndAutodiff) {
  FunctionValues scales{}, a = DefaultFunctionValues(), b = a, c = a;
  for (int f = 0; f < kNumFunctions; ++f) {
    scales[f] = f == kTau ? 0.0 : 0.5 + 0.25 * f;
    b[f] += 0.01 * f;
    c[f] -= 0.02 * f * f;
  }
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessResidual::Create(1.7, scales));
  const double* parameters[] = {a.data(), b.data(), c.data()};
  const std::vector<const ceres::Manifold*> manifolds(3, nullptr);
  ceres::GradientChecker checker(cost.get(), &manifolds,
                                 ceres::NumericDiffOptions());
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters, 1e-9, &results)) << results.error_log;

  ceres::AutoDiffCostFunction<TemplatedSmoothness, kNumFunctions, kNumFunctions,
                              kNumFunctions, kNumFunctions>
      autodiff(new TemplatedSmoothness{scales});
  std::vector<double> r1(kNumFunctions), r2(kNumFunctions);
  std::vector<std::vector<double>> j1(3), j2(3);
  double* jac1[3];
  double* jac2[3];
  for (int i = 0; i < 3; ++i) {
    j1[i].assign(kNumFunctions * kNumFunctions, 1.0);
    j2[i].assign(kNumFunctions * kNumFunctions, 2.0);
    jac1[i] = j1[i].data();
    jac2[i] = j2[i].data();
  }
  ASSERT_TRUE(cost->Evaluate(parameters, r1.data(), jac1));
  ASSERT_TRUE(autodiff.Evaluate(parameters, r2.data(), jac2));
  EXPECT_EQ(r1, r2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(j1[i], j2[i]);
}

TEST(PriorResidualTest, JacobianMatchesNumericDifferences) {
  FunctionValues scales{}, prior = DefaultFunctionValues(), values = prior;
  for (int f = 0; f < kNumFunctions; ++f) {
    scales[f] = 1.0 + f;
    values[f] += 0.03 * f;
  }
  std::unique_ptr<ceres::CostFunction> cost(
      PriorResidual::Create(0.4, scales, prior));
  const double* parameters[] = {values.data()};
  const std::vector<const ceres::Manifold*> manifolds(1, nullptr);
  ceres::GradientChecker checker(cost.get(), &manifolds,
                                 ceres::NumericDiffOptions());
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters, 1e-9, &results)) << results.error_log;
}

}  // namespace
}  // namespace pfdm
