// The explicit Lagrangian integrator's forward Euler (the paper's method,
// IntegratorKind::kEuler) on toy problems whose steps can be worked out by
// hand; RKC's tests are in rkc_test.cc.
#include <cmath>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "ceres/autodiff_cost_function.h"
#include "ceres/problem.h"
#include "glog/logging.h"
#include "gtest/gtest.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/testing/toy_problems.h"

namespace pfdm {
namespace {

// Ceres logs every non-finite residual at length; these tests make them.
class QuietCeres {
 public:
  QuietCeres() : saved_(FLAGS_minloglevel) {
    FLAGS_minloglevel = google::ERROR;
  }
  ~QuietCeres() { FLAGS_minloglevel = saved_; }

 private:
  int saved_;
};

TEST(IntegratorTest, OneStepIsForwardEulerWithJacobiDamping) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kJacobi;
  toy.options.time_step = 0.3;
  toy.options.max_steps = 1;
  const SolverReport report = toy.Solve();
  const Eigen::Vector2d d =
      (LinearJacobian().transpose() * LinearJacobian()).diagonal();
  const Eigen::Vector2d expected =
      Eigen::Vector2d(5.0, -3.0) -
      0.3 * LinearGradient({5.0, -3.0}).cwiseQuotient(d);
  EXPECT_NEAR(toy.x[0], expected[0], 1e-12);
  EXPECT_NEAR(toy.x[1], expected[1], 1e-12);
  EXPECT_EQ(report.iterations, 1);
  EXPECT_EQ(report.residual_evaluations, 2);
  EXPECT_DOUBLE_EQ(report.trace.back().pseudo_time, 0.3);
}

TEST(IntegratorTest, OneStepUsesTheDampingScales) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kJacobi;
  toy.options.time_step = 0.3;
  toy.options.max_steps = 1;
  toy.options.damping_scale[toy.x] = {2.0, 0.5};
  toy.Solve();
  const Eigen::Vector2d d = (LinearJacobian().transpose() * LinearJacobian())
                                .diagonal()
                                .cwiseProduct(Eigen::Vector2d(2.0, 0.5));
  const Eigen::Vector2d expected =
      Eigen::Vector2d(5.0, -3.0) -
      0.3 * LinearGradient({5.0, -3.0}).cwiseQuotient(d);
  EXPECT_NEAR(toy.x[0], expected[0], 1e-12);
  EXPECT_NEAR(toy.x[1], expected[1], 1e-12);
}

TEST(IntegratorTest, UnitDampingIsPlainGradientFlow) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kUnit;
  toy.options.time_step = 1e-3;
  toy.options.max_steps = 1;
  toy.Solve();
  const Eigen::Vector2d expected =
      Eigen::Vector2d(5.0, -3.0) - 1e-3 * LinearGradient({5.0, -3.0});
  EXPECT_NEAR(toy.x[0], expected[0], 1e-12);
  EXPECT_NEAR(toy.x[1], expected[1], 1e-12);
}

// Scaling D changes the path and the stable step, not the rest point.
TEST(IntegratorTest, ScaledAndUnitDampingRestAtTheMinimum) {
  for (const DampingKind kind : {DampingKind::kJacobi, DampingKind::kUnit}) {
    LinearToyProblem toy(SolverKind::kIntegrator);
    toy.options.integrator = IntegratorKind::kEuler;
    toy.options.damping = kind;
    toy.options.damping_scale[toy.x] = {2.0, 0.5};
    toy.options.rest_tolerance = 1e-9;
    const SolverReport report = toy.Solve();
    EXPECT_EQ(report.termination, "REST");
    EXPECT_NEAR(toy.x[0], 1.0, 1e-6);
    EXPECT_NEAR(toy.x[1], 2.0, 1e-6);
  }
}

// LinearResidual with x0 and x1 in blocks of their own.
struct LinearInTwoBlocks {
  template <typename T>
  bool operator()(const T* x0, const T* x1, T* r) const {
    const T x[2] = {x0[0], x1[0]};
    return LinearResidual()(x, r);
  }
};

// The integrator's path is the same wherever the blocks lie in memory:
// their order comes from the residuals, not from their addresses.
TEST(IntegratorTest, ThePathDoesNotDependOnWhereTheBlocksLie) {
  std::vector<double> path[2];
  double ends[2][2];
  for (int layout = 0; layout < 2; ++layout) {
    double memory[2] = {0.0, 0.0};
    // Layout 0 puts x0 first in memory, layout 1 x1.
    double* x0 = &memory[layout];
    double* x1 = &memory[1 - layout];
    *x0 = 5.0;
    *x1 = -3.0;
    ceres::Problem problem;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<LinearInTwoBlocks, 3, 1, 1>(
            new LinearInTwoBlocks),
        nullptr, x0, x1);
    SolverOptions options;
    options.kind = SolverKind::kIntegrator;
    options.integrator = IntegratorKind::kEuler;
    options.damping = DampingKind::kUnit;
    options.on_step = [&](const SolverTracePoint& point) {
      path[layout].push_back(point.cost);
    };
    SolveProblem(&problem, options);
    ends[layout][0] = *x0;
    ends[layout][1] = *x1;
  }
  ASSERT_GT(path[0].size(), 10u);
  EXPECT_EQ(path[0], path[1]);  // Bit for bit.
  EXPECT_EQ(ends[0][0], ends[1][0]);
  EXPECT_EQ(ends[0][1], ends[1][1]);
}

TEST(IntegratorTest, BadDampingScalesAreRefused) {
  const std::vector<std::vector<double>> bad = {
      {1.0}, {1.0, 0.0}, {1.0, -2.0}, {std::nan(""), 1.0}};
  for (const std::vector<double>& scale : bad) {
    LinearToyProblem toy(SolverKind::kIntegrator);
    toy.options.integrator = IntegratorKind::kEuler;
    toy.options.damping_scale[toy.x] = scale;
    const SolverReport report = toy.Solve();
    EXPECT_FALSE(report.usable);
    EXPECT_NE(report.message.find("damping scale"), std::string::npos)
        << report.message;
    EXPECT_EQ(toy.x[0], 5.0);  // Untouched.
  }
}

TEST(IntegratorTest, ChoosesAStepBelowTheStabilityBound) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kJacobi;
  toy.options.max_steps = 1;
  const SolverReport report = toy.Solve();
  ASSERT_EQ(report.trace.size(), 2u);
  const double dt = report.trace[1].pseudo_time;
  EXPECT_LT(dt, LinearStabilityBound());
  EXPECT_GT(dt, 0.8 * LinearStabilityBound());  // Not needlessly small.
}

// Past 2 / lambda_max forward Euler diverges (here each step would multiply
// the energy by about (1 - 5)^2); such a step is undone and dt halved until
// it is stable, and the energy never rises.
TEST(IntegratorTest, RefusesStepsAboveTheStabilityBound) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kJacobi;
  toy.options.time_step = 2.5 * LinearStabilityBound();
  toy.options.rest_tolerance = 1e-9;
  const SolverReport report = toy.Solve();
  EXPECT_TRUE(report.usable);
  EXPECT_EQ(report.termination, "REST");
  EXPECT_NEAR(toy.x[1], 2.0, 1e-7);
  ASSERT_GE(report.trace.size(), 2u);
  // 2.5 and 1.25 times the bound refused, 0.625 taken.
  EXPECT_DOUBLE_EQ(report.trace[1].pseudo_time, toy.options.time_step / 4);
  EXPECT_EQ(report.residual_evaluations, report.iterations + 3);
  for (size_t i = 1; i < report.trace.size(); ++i) {
    EXPECT_LE(report.trace[i].cost, report.trace[i - 1].cost);
  }
}

TEST(IntegratorTest, StepsIntoNaNAreRefused) {
  const QuietCeres quiet;
  ScalarToyProblem<SquareRootResidual> toy(4.0, SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.time_step = 1000.0;  // The first step lands far below x = 0.
  const SolverReport report = toy.Solve();
  EXPECT_TRUE(report.usable) << report.message;
  EXPECT_NEAR(toy.x[0], 1.0, 1e-4);
}

TEST(IntegratorTest, NaNAtTheStartIsUnusable) {
  const QuietCeres quiet;
  ScalarToyProblem<SquareRootResidual> toy(-1.0, SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  const SolverReport report = toy.Solve();
  EXPECT_FALSE(report.usable);
  EXPECT_EQ(report.termination, "FAILURE");
  EXPECT_NE(report.message.find("not finite"), std::string::npos);
  EXPECT_EQ(toy.x[0], -1.0);
}

// The model damping D = J^T J (docs/dynamics.md): on a linear problem
// D^-1 J^T J = I, so every mode decays at rate 1 and a step dt multiplies
// the distance to the minimum by 1 - dt, whatever the stiffness ratio
// (here 100 x 100).
TEST(IntegratorTest, ModelDampingDecaysEveryModeAtRateOne) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kModel;
  toy.options.time_step = 0.25;
  toy.options.max_steps = 1;
  toy.Solve();
  EXPECT_NEAR(toy.x[0], 1.0 + 0.75 * (5.0 - 1.0), 1e-8);
  EXPECT_NEAR(toy.x[1], 2.0 + 0.75 * (-3.0 - 2.0), 1e-8);
}

// The default step 1 / lambda_max takes every mode to rest at once: the
// next step finds nothing left to dissipate.
TEST(IntegratorTest, ModelDampingRestsInTwoSteps) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kModel;
  toy.options.rest_tolerance = 1e-9;
  const SolverReport report = toy.Solve();
  EXPECT_EQ(report.termination, "REST");
  EXPECT_LE(report.iterations, 2);
  EXPECT_NEAR(toy.x[0], 1.0, 1e-8);
  EXPECT_NEAR(toy.x[1], 2.0, 1e-8);
}

// With x0 <= 0.5 the minimum (1, 2) is out of bounds; the constrained one
// holds x0 at 0.5 and x1 where the free force vanishes, 100 (x1 - 2) +
// 0.01 (x1 - 2.5) = 0.  The coupled D (the 0.1 x0 + 0.1 x1 residual) would
// keep pushing x1 if the held coordinate's force stayed in D^-1 g.
TEST(IntegratorTest, ModelDampingRestsAtTheBoundedMinimum) {
  for (const IntegratorKind kind :
       {IntegratorKind::kEuler, IntegratorKind::kRkc}) {
    LinearToyProblem toy(SolverKind::kIntegrator);
    toy.x[0] = 0.0;
    toy.problem.SetParameterUpperBound(toy.x, 0, 0.5);
    toy.options.integrator = kind;
    toy.options.damping = DampingKind::kModel;
    toy.options.rest_tolerance = 1e-9;
    const SolverReport report = toy.Solve();
    EXPECT_EQ(report.termination, "REST") << IntegratorName(kind);
    // Euler removes the free mode in a step; two RKC stages halve it per
    // step (R(-1) = 1/2): 30 halvings to 1e-9.
    EXPECT_LT(report.jacobian_evaluations,
              kind == IntegratorKind::kEuler ? 10 : 200)
        << IntegratorName(kind);
    EXPECT_DOUBLE_EQ(toy.x[0], 0.5) << IntegratorName(kind);
    EXPECT_NEAR(toy.x[1], 200.025 / 100.01, 1e-8) << IntegratorName(kind);
  }
}

// The model damping is D(q) = J(q)^T J(q), taken at each step's start:
// on r = x^2 - 4 a step of dt = 1 is then Newton's x - (x^2 - 4) / (2x),
// 3 -> 2.1666667 -> 2.0064103 (a D frozen at x = 3 would give 2.0831).
TEST(IntegratorTest, ModelDampingIsTakenAtEachStepsStart) {
  ScalarToyProblem<QuadraticResidual> toy(3.0, SolverKind::kIntegrator);
  toy.options.integrator = IntegratorKind::kEuler;
  toy.options.damping = DampingKind::kModel;
  toy.options.time_step = 1.0;
  toy.options.max_steps = 2;
  const SolverReport report = toy.Solve();
  EXPECT_EQ(report.iterations, 2);
  const double x1 = 3.0 - 5.0 / 6.0;
  EXPECT_NEAR(toy.x[0], x1 - (x1 * x1 - 4.0) / (2.0 * x1), 1e-8);
}

}  // namespace
}  // namespace pfdm
