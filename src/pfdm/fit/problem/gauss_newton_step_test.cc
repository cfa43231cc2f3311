#include "pfdm/fit/problem/gauss_newton_step.h"

#include <array>
#include <cmath>
#include <vector>

#include "ceres/ceres.h"
#include "ceres/rotation.h"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

// A rotated and shifted point against its target: R(q) p + t - target.
struct RotatedPoint {
  RotatedPoint(const std::array<double, 3>& p, const std::array<double, 3>& t)
      : point(p), target(t) {}
  template <typename T>
  bool operator()(const T* q, const T* shift, T* residual) const {
    const T p[3] = {T(point[0]), T(point[1]), T(point[2])};
    T rotated[3];
    ceres::UnitQuaternionRotatePoint(q, p, rotated);
    for (int i = 0; i < 3; ++i) {
      residual[i] = rotated[i] + shift[i] * shift[i] - T(target[i]);
    }
    return true;
  }
  std::array<double, 3> point, target;
};

// A problem with a manifold (the quaternion) and a bound (the shift's
// first entry), its minimum away from the start.
struct TestProblem {
  TestProblem() {
    const std::array<std::array<double, 3>, 4> points = {
        {{10, 0, 0}, {0, 10, 0}, {0, 0, 10}, {5, 5, -5}}};
    for (const auto& p : points) {
      const std::array<double, 3> target = {p[0] * 0.98 - p[1] * 0.2 + 1.5,
                                            p[0] * 0.2 + p[1] * 0.98 + 0.8,
                                            p[2] + 0.3};
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<RotatedPoint, 3, 4, 3>(
              new RotatedPoint(p, target)),
          nullptr, q.data(), shift.data());
    }
    problem.SetManifold(q.data(), new ceres::QuaternionManifold);
    problem.SetParameterLowerBound(shift.data(), 0, 1.3);
  }
  // Of unit norm: (0.99, 0.05, -0.02, 0.1) / 0.99649...
  std::array<double, 4> q = {0.9934833, 0.05017592, -0.02007037, 0.10035185};
  std::array<double, 3> shift = {1.4, 0.9, 0.5};
  ceres::Problem problem;
};

// The step is where Ceres' first Levenberg-Marquardt iteration lands from
// the same radius (it accepts the step here): the quaternion moved on its
// manifold (still of unit norm), the bounded entry clamped at its bound.
TEST(GaussNewtonStepTest, LandsWhereCeresFirstIterationDoes) {
  TestProblem ours, theirs;
  ASSERT_TRUE(TakeGaussNewtonStep(1e8, &ours.problem));
  ceres::Solver::Options options;
  options.max_num_iterations = 1;
  options.initial_trust_region_radius = 1e8;
  options.max_num_line_search_step_size_iterations = 0;
  options.linear_solver_type = ceres::DENSE_QR;
  options.function_tolerance = 0.0;
  options.gradient_tolerance = 0.0;
  options.parameter_tolerance = 0.0;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &theirs.problem, &summary);
  ASSERT_EQ(summary.iterations.size(), 2u);
  ASSERT_TRUE(summary.iterations.back().step_is_successful);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(ours.q[i], theirs.q[i], 1e-10) << i;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(ours.shift[i], theirs.shift[i], 1e-10) << i;
  }
  EXPECT_NEAR(std::hypot(std::hypot(ours.q[0], ours.q[1]),
                         std::hypot(ours.q[2], ours.q[3])),
              1.0, 1e-7);
  EXPECT_EQ(ours.shift[0], 1.3);
  EXPECT_GT(std::abs(ours.q[1] - 0.05017592), 1e-2);  // It did move.
}

// With every block held there is no step: false, nothing moved.
TEST(GaussNewtonStepTest, HeldBlocksStay) {
  TestProblem held;
  held.problem.SetParameterBlockConstant(held.q.data());
  held.problem.SetParameterBlockConstant(held.shift.data());
  EXPECT_FALSE(TakeGaussNewtonStep(1e8, &held.problem));
  EXPECT_EQ(held.q[3], 0.10035185);
  EXPECT_EQ(held.shift[1], 0.9);
}

// r = atan(x) from x = 2: the Gauss-Newton step -r / r' = -5.5 lands at
// -3.54, where |r| is larger.  Ceres rejects it and so does the step:
// false, x where it was.
struct Arctangent {
  template <typename T>
  bool operator()(const T* x, T* residual) const {
    residual[0] = atan(x[0]);
    return true;
  }
};

TEST(GaussNewtonStepTest, AStepThatRaisesTheCostIsNotTaken) {
  double ours = 2.0, theirs = 2.0;
  ceres::Problem mine, ceres_problem;
  mine.AddResidualBlock(
      new ceres::AutoDiffCostFunction<Arctangent, 1, 1>(new Arctangent),
      nullptr, &ours);
  ceres_problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<Arctangent, 1, 1>(new Arctangent),
      nullptr, &theirs);
  EXPECT_FALSE(TakeGaussNewtonStep(1e8, &mine));
  EXPECT_EQ(ours, 2.0);
  // Untested (verify declines the test), the step stands.
  EXPECT_TRUE(TakeGaussNewtonStep(1e8, &mine, [] { return false; }));
  EXPECT_NEAR(ours, 2.0 - std::atan(2.0) * 5.0, 1e-6);
  ceres::Solver::Options options;
  options.max_num_iterations = 1;
  options.initial_trust_region_radius = 1e8;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &ceres_problem, &summary);
  EXPECT_FALSE(summary.iterations.back().step_is_successful);
  EXPECT_EQ(theirs, 2.0);
}

}  // namespace
}  // namespace pfdm
