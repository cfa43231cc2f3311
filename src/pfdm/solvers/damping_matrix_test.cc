// The integrators' damping matrix against hand-computed ones: the model
// damping is J^T J (floored, scaled), its rates are 1, and a bound's held
// coordinates leave the others to the reduced system.
#include "pfdm/solvers/damping_matrix.h"

#include <optional>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/testing/toy_problems.h"

namespace pfdm {
namespace {

std::optional<DampingMatrix> BuildFor(LinearToyProblem* toy,
                                      ceres::CRSMatrix* jacobian) {
  const State state = FreeBlocks(toy->problem);
  Evaluation e;
  EXPECT_TRUE(Evaluate(&toy->problem, state, 1, true, &e));
  *jacobian = e.jacobian;
  std::string error;
  std::optional<DampingMatrix> d = DampingMatrix::Build(
      toy->problem, state, e.jacobian, toy->options, &error);
  EXPECT_TRUE(d.has_value()) << error;
  return d;
}

// D = S^1/2 (J^T J + 1e-9 diag(J^T J)) S^1/2, column by column.
TEST(DampingMatrixTest, ModelDampingIsTheScaledGaussNewtonMatrix) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.damping = DampingKind::kModel;
  toy.options.damping_scale[toy.x] = {2.0, 0.5};
  ceres::CRSMatrix j;
  const std::optional<DampingMatrix> d = BuildFor(&toy, &j);
  ASSERT_TRUE(d.has_value());
  EXPECT_FALSE(d->diagonal());
  Eigen::Matrix2d h = LinearJacobian().transpose() * LinearJacobian();
  h.diagonal() *= 1.0 + DampingMatrix::kModelFloor;
  const Eigen::Vector2d root(std::sqrt(2.0), std::sqrt(0.5));
  const Eigen::Matrix2d expected = root.asDiagonal() * h * root.asDiagonal();
  for (int c = 0; c < 2; ++c) {
    std::vector<double> unit(2, 0.0);
    unit[c] = 1.0;
    const std::vector<double> column = d->Apply(unit);
    for (int r = 0; r < 2; ++r) {
      EXPECT_NEAR(column[r], expected(r, c), 1e-12 * expected.norm());
    }
  }
  EXPECT_NEAR(
      d->Norm({1.0, -1.0}),
      std::sqrt(Eigen::Vector2d(1, -1).dot(expected * Eigen::Vector2d(1, -1))),
      1e-12);
}

// With D = J^T J every mode of D^-1 J^T J has rate 1 (the floor takes
// 1e-9 of it); with Jacobi damping the rate is LargestEigenvalue's.
TEST(DampingMatrixTest, ModelDampingRatesAreOne) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.damping = DampingKind::kModel;
  ceres::CRSMatrix j;
  const std::optional<DampingMatrix> model = BuildFor(&toy, &j);
  ASSERT_TRUE(model.has_value());
  EXPECT_NEAR(model->LargestRate(j), 1.0, 1e-8);
  toy.options.damping = DampingKind::kJacobi;
  const std::optional<DampingMatrix> jacobi = BuildFor(&toy, &j);
  ASSERT_TRUE(jacobi.has_value());
  EXPECT_TRUE(jacobi->diagonal());
  EXPECT_NEAR(jacobi->LargestRate(j), 2.0 / LinearStabilityBound(), 1e-3);
}

// D = (2 1; 1 3), g = (1, 1): free, f = -D^-1 g = -(2, 1) / 5; with x1
// held, D_00 f0 = -g0: f = (-0.5, 0).
TEST(DampingMatrixTest, HeldCoordinatesLeaveTheReducedSystem) {
  const std::optional<DampingMatrix> d =
      DampingMatrix::FromDense((Eigen::Matrix2d() << 2, 1, 1, 3).finished());
  ASSERT_TRUE(d.has_value());
  const std::vector<double> free = d->Velocity({1.0, 1.0}, {false, false});
  EXPECT_NEAR(free[0], -0.4, 1e-15);
  EXPECT_NEAR(free[1], -0.2, 1e-15);
  for (int repeat = 0; repeat < 2; ++repeat) {  // The cached factor too.
    const std::vector<double> held = d->Velocity({1.0, 1.0}, {false, true});
    EXPECT_NEAR(held[0], -0.5, 1e-15);
    EXPECT_EQ(held[1], 0.0);
  }
  EXPECT_FALSE(
      DampingMatrix::FromDense((Eigen::Matrix2d() << 1, 2, 2, 1).finished())
          .has_value());  // Not positive definite.
}

// x0 on its upper bound 0.5 with the force pushing it up is held; x1 is
// not.
TEST(DampingMatrixTest, HeldAtBoundsIsTheOutwardPush) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.x[0] = 0.5;
  toy.problem.SetParameterUpperBound(toy.x, 0, 0.5);
  const State state = FreeBlocks(toy.problem);
  const std::vector<bool> up = HeldAtBounds(toy.problem, state, {-1.0, 1.0});
  EXPECT_TRUE(up[0]);
  EXPECT_FALSE(up[1]);
  const std::vector<bool> down = HeldAtBounds(toy.problem, state, {1.0, 1.0});
  EXPECT_FALSE(down[0]);
}

}  // namespace
}  // namespace pfdm
