#include "pfdm/fit/residuals/axis_gauge_chain.h"

#include <memory>
#include <vector>

#include "ceres/ceres.h"
#include "ceres/gradient_checker.h"
#include "ceres/normal_prior.h"
#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

constexpr int kKnots = 6;
constexpr double kSqrtWeight = 3.0;

// Knots whose ring centres have a mean and a trend for the gauge to see.
std::vector<FunctionValues> OffsetKnots() {
  std::vector<FunctionValues> knots(kKnots, DefaultFunctionValues());
  for (int k = 0; k < kKnots; ++k) {
    knots[k][kE1o] = 1.5 + 0.4 * k - 0.1 * k * k;
    knots[k][kE2o] = -0.7 + 0.25 * (k % 3);
  }
  return knots;
}

std::vector<double*> Pointers(std::vector<FunctionValues>* knots) {
  std::vector<double*> pointers;
  for (FunctionValues& knot : *knots) pointers.push_back(knot.data());
  return pointers;
}

// 1/2 |r|^2 of AxisGaugeResidual.
double DenseCost(const std::vector<double*>& knots) {
  AxisGaugeResidual dense(kKnots, kSqrtWeight);
  double r[4];
  EXPECT_TRUE(dense.Evaluate(knots.data(), r, nullptr));
  return 0.5 * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
}

// Adds the chain to `problem` over `knots` (whole blocks).
void AddChain(AxisGaugeChain* chain, const std::vector<double*>& knots,
              ceres::Problem* problem) {
  for (int k = 0; k < kKnots; ++k) {
    std::vector<double*> blocks = chain->LinkSums(k);
    blocks.push_back(knots[k]);
    problem->AddResidualBlock(chain->Link(k), nullptr, blocks);
  }
  problem->AddResidualBlock(chain->End(), nullptr, chain->sum(kKnots - 1));
}

TEST(AxisGaugeChainTest, StartsAtTheDenseGaugesCostWithNoPullOnItsSums) {
  std::vector<FunctionValues> knots = OffsetKnots();
  const std::vector<double*> pointers = Pointers(&knots);
  std::vector<const double*> values(pointers.begin(), pointers.end());
  AxisGaugeChain chain(values, kSqrtWeight);
  ceres::Problem problem;
  AddChain(&chain, pointers, &problem);

  ceres::Problem::EvaluateOptions sums_only;
  for (int k = 0; k < kKnots; ++k) {
    sums_only.parameter_blocks.push_back(chain.sum(k));
  }
  double cost = 0.0;
  std::vector<double> gradient;
  ASSERT_TRUE(problem.Evaluate(sums_only, &cost, nullptr, &gradient, nullptr));
  const double dense = DenseCost(pointers);
  ASSERT_GT(dense, 1.0);
  EXPECT_NEAR(cost, dense, 1e-12 * dense);
  ASSERT_EQ(gradient.size(), 4u * kKnots);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-12 * dense);
}

// The chain and AxisGaugeResidual pull the same knots to the same place:
// with a quadratic pull of each knot toward where it started, both problems
// have one minimum, the same to round-off.
TEST(AxisGaugeChainTest, ReachesTheDenseGaugesMinimum) {
  const std::vector<FunctionValues> start = OffsetKnots();
  auto solve = [&](bool chained) {
    std::vector<FunctionValues> knots = start;
    const std::vector<double*> pointers = Pointers(&knots);
    std::vector<const double*> values(pointers.begin(), pointers.end());
    AxisGaugeChain chain(values, kSqrtWeight);
    ceres::Problem problem;
    for (int k = 0; k < kKnots; ++k) {
      ceres::Vector target =
          Eigen::Map<const ceres::Vector>(start[k].data(), kNumFunctions);
      problem.AddResidualBlock(
          new ceres::NormalPrior(
              ceres::Matrix::Identity(kNumFunctions, kNumFunctions), target),
          nullptr, pointers[k]);
    }
    if (chained) {
      AddChain(&chain, pointers, &problem);
    } else {
      problem.AddResidualBlock(new AxisGaugeResidual(kKnots, kSqrtWeight),
                               nullptr, pointers);
    }
    // Linear least squares: one undamped step is the minimum.
    ceres::Solver::Options options;
    options.initial_trust_region_radius = options.max_trust_region_radius;
    options.max_num_iterations = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    EXPECT_TRUE(summary.IsSolutionUsable());
    return knots;
  };
  const std::vector<FunctionValues> dense = solve(false);
  const std::vector<FunctionValues> chained = solve(true);
  double moved = 0.0;
  for (int k = 0; k < kKnots; ++k) {
    moved = std::max(moved, std::abs(dense[k][kE1o] - start[k][kE1o]));
    for (int f = 0; f < kNumFunctions; ++f) {
      EXPECT_NEAR(chained[k][f], dense[k][f], 1e-12)
          << "knot " << k << " f " << f;
    }
  }
  EXPECT_GT(moved, 0.1);  // The gauge did move the offsets.
}

TEST(AxisGaugeChainTest, LinkJacobiansMatchNumericDifferences) {
  std::vector<FunctionValues> knots = OffsetKnots();
  const std::vector<double*> pointers = Pointers(&knots);
  const double previous[4] = {0.3, -1.2, 0.8, 2.0};
  const double sum[4] = {1.1, 0.4, -0.6, 0.9};
  for (int k : {0, 3}) {
    AxisGaugeLinkResidual link(k, kKnots, kSqrtWeight);
    std::vector<const double*> parameters;
    if (k > 0) parameters.push_back(previous);
    parameters.push_back(sum);
    parameters.push_back(pointers[k]);
    const std::vector<const ceres::Manifold*> manifolds(parameters.size(),
                                                        nullptr);
    ceres::GradientChecker checker(&link, &manifolds,
                                   ceres::NumericDiffOptions());
    ceres::GradientChecker::ProbeResults results;
    EXPECT_TRUE(checker.Probe(parameters.data(), 1e-9, &results))
        << "link " << k << ": " << results.error_log;
  }
}

}  // namespace
}  // namespace pfdm
