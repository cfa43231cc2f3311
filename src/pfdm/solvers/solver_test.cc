#include "pfdm/solvers/solver.h"

#include <cmath>
#include <limits>

#include "ceres/autodiff_cost_function.h"
#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

struct Quadratic {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] * x[0] - 4.0;
    return true;
  }
};

TEST(SolverTest, NamesRoundTripAndUnknownNamesAreErrors) {
  for (SolverKind kind :
       {SolverKind::kDirect, SolverKind::kDamped, SolverKind::kIntegrator}) {
    EXPECT_EQ(SolverFromName(SolverName(kind)), kind);
  }
  try {
    SolverFromName("newton");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "unknown --solver 'newton' (expected direct, damped or "
                 "integrator)");
  }
}

TEST(SolverTest, DirectSolveReportsItsIterations) {
  double x = 5.0;
  ceres::Problem problem;
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<Quadratic, 1, 1>(new Quadratic), nullptr,
      &x);
  const SolverReport report = SolveDirect(&problem, SolverOptions());
  EXPECT_NEAR(x, 2.0, 1e-8);
  EXPECT_TRUE(report.usable);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.termination, "CONVERGENCE");
  EXPECT_EQ(static_cast<int>(report.trace.size()), report.iterations + 1);
  EXPECT_GT(report.trace.front().cost, report.trace.back().cost);
  EXPECT_GE(report.jacobian_evaluations, report.iterations);
  EXPECT_GE(report.residual_evaluations, report.iterations);
  for (const SolverTracePoint& point : report.trace) {
    EXPECT_EQ(point.pseudo_time, 0.0);  // No dynamics, no pseudo-time.
  }
}

TEST(SolverTest, DirectSolveOfNaNIsUnusable) {
  double x = std::numeric_limits<double>::quiet_NaN();
  ceres::Problem problem;
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<Quadratic, 1, 1>(new Quadratic), nullptr,
      &x);
  const SolverReport report = SolveDirect(&problem, SolverOptions());
  EXPECT_FALSE(report.usable);
  EXPECT_EQ(report.termination, "FAILURE");
  EXPECT_FALSE(report.message.empty());
}

// Each kind reaches x = 2 its own way: the dynamics in pseudo-time, the
// integrator with one evaluation per step.
TEST(SolverTest, SolveProblemDispatchesOnTheKind) {
  for (SolverKind kind :
       {SolverKind::kDirect, SolverKind::kDamped, SolverKind::kIntegrator}) {
    double x = 5.0;
    ceres::Problem problem;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Quadratic, 1, 1>(new Quadratic),
        nullptr, &x);
    SolverOptions options;
    options.kind = kind;
    const SolverReport report = SolveProblem(&problem, options);
    EXPECT_NEAR(x, 2.0, 1e-5) << SolverName(kind);
    EXPECT_EQ(report.trace.back().pseudo_time > 0.0,
              kind != SolverKind::kDirect)
        << SolverName(kind);
    EXPECT_EQ(report.termination == "REST", kind != SolverKind::kDirect)
        << SolverName(kind);
    if (kind == SolverKind::kIntegrator) {
      EXPECT_EQ(report.jacobian_evaluations, report.residual_evaluations);
      EXPECT_GE(report.residual_evaluations, report.iterations + 1);
    }
  }
}

// What on_step throws stops every kind of solve at the step it was thrown
// on and reaches the caller (how the Python module's Ctrl-C ends a fit).
TEST(SolverTest, AnExceptionFromOnStepStopsTheSolveAndReachesTheCaller) {
  struct Stop {
    int iteration;
  };
  for (SolverKind kind :
       {SolverKind::kDirect, SolverKind::kDamped, SolverKind::kIntegrator}) {
    double x = 5.0;
    ceres::Problem problem;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Quadratic, 1, 1>(new Quadratic),
        nullptr, &x);
    SolverOptions options;
    options.kind = kind;
    int steps = 0;
    options.on_step = [&steps](const SolverTracePoint& point) {
      ++steps;
      if (point.iteration == 1) throw Stop{point.iteration};
    };
    try {
      SolveProblem(&problem, options);
      ADD_FAILURE() << SolverName(kind) << " finished";
    } catch (const Stop& stop) {
      EXPECT_EQ(stop.iteration, 1) << SolverName(kind);
    }
    EXPECT_EQ(steps, 2) << SolverName(kind);
    EXPECT_GT(std::abs(x - 2.0), 1e-3) << SolverName(kind);  // Not solved.
  }
}

}  // namespace
}  // namespace pfdm
