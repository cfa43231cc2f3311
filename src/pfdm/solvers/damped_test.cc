// Damped stepping inside Ceres (SolverKind::kDamped) on a toy problem whose
// step can be worked out by hand.
#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/testing/toy_problems.h"

namespace pfdm {
namespace {

// Ceres' LM step with the trust region pinned at dt is the linearly
// implicit Euler step (J^T J + diag(J^T J) / dt) dq = -J^T r.
TEST(DampedTest, OneStepIsImplicitEulerWithJacobiDamping) {
  LinearToyProblem toy(SolverKind::kDamped);
  toy.options.time_step = 0.3;
  toy.options.max_steps = 1;
  const SolverReport report = toy.Solve();
  const Eigen::Matrix2d h = LinearJacobian().transpose() * LinearJacobian();
  const Eigen::Matrix2d system =
      h + Eigen::Matrix2d(h.diagonal().asDiagonal()) / 0.3;
  const Eigen::Vector2d expected =
      Eigen::Vector2d(5.0, -3.0) -
      system.ldlt().solve(LinearGradient({5.0, -3.0}));
  EXPECT_NEAR(toy.x[0], expected[0], 1e-10);
  EXPECT_NEAR(toy.x[1], expected[1], 1e-10);
  EXPECT_EQ(report.iterations, 1);
}

TEST(DampedTest, PseudoTimeAdvancesByTheFixedStep) {
  LinearToyProblem toy(SolverKind::kDamped);
  toy.options.time_step = 0.5;
  const SolverReport report = toy.Solve();
  EXPECT_EQ(report.termination, "REST");
  ASSERT_GE(report.trace.size(), 3u);
  for (size_t i = 0; i < report.trace.size(); ++i) {
    EXPECT_DOUBLE_EQ(report.trace[i].pseudo_time, 0.5 * i);
  }
}

}  // namespace
}  // namespace pfdm
