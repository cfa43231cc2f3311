#include "pfdm/fit/residuals/regularizer.h"

#include <memory>
#include <vector>

#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

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

}  // namespace
}  // namespace pfdm
