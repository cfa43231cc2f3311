#include "pfdm/solvers/active_bounds.h"

#include <cmath>
#include <cstdio>

#include "Eigen/Dense"
#include "ceres/autodiff_cost_function.h"
#include "ceres/problem.h"
#include "ceres/solver.h"
#include "gtest/gtest.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {
namespace {

// r = A x - b, four residuals over x in R^3, the columns of A strongly
// coupled (0.9 between x0 and x1): a step that clips x0 moves x1 wrongly.
Eigen::Matrix<double, 4, 3> CoupledMatrix() {
  Eigen::Matrix<double, 4, 3> a;
  a << 1.0, 0.9, 0.0, 0.9, 1.0, 0.5, 0.0, 0.5, 1.0, 0.3, 0.0, 0.2;
  return a;
}

struct Linear {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    const Eigen::Matrix<double, 4, 3> a = CoupledMatrix();
    for (int i = 0; i < 4; ++i) {
      r[i] = a(i, 0) * x[0] + a(i, 1) * x[1] + a(i, 2) * x[2] - T(b[i]);
    }
    return true;
  }
  Eigen::Vector4d b;
};

// The problem's unconstrained minimum is `minimum` (zero cost); x0 >= 0.
struct BoundedToy {
  BoundedToy(const Eigen::Vector3d& minimum, const Eigen::Vector3d& start) {
    b = CoupledMatrix() * minimum;
    x = start;
    auto* functor = new Linear{b};
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Linear, 4, 3>(functor), nullptr,
        x.data());
    problem.SetParameterLowerBound(x.data(), 0, 0.0);
  }
  Eigen::Vector4d b;
  Eigen::Vector3d x;
  ceres::Problem problem;
};

// The unconstrained minimum has x0 = -1: the constrained one holds x0 at 0
// and is the least squares of x1, x2 alone, reached to 2e-8 in 2
// iterations, the problem left without a manifold.  Ceres clipping alone
// (the same options) ran out of its 50 iterations 0.10 from it.
TEST(ActiveBoundsTest, AnActiveBoundIsHeldAndTheRestSolvedExactly) {
  BoundedToy toy(Eigen::Vector3d(-1.0, 2.0, 1.0), Eigen::Vector3d(1, 1, 1));
  const Eigen::Vector2d rest =
      CoupledMatrix().rightCols<2>().colPivHouseholderQr().solve(toy.b);
  const SolverReport report = SolveDirect(&toy.problem, SolverOptions());
  EXPECT_TRUE(report.usable);
  EXPECT_TRUE(report.converged) << report.termination;
  EXPECT_EQ(toy.x[0], 0.0);
  EXPECT_NEAR(toy.x[1], rest[0], 1e-6);  // 2e-8 off: the solve's tolerance.
  EXPECT_NEAR(toy.x[2], rest[1], 1e-6);
  EXPECT_LE(report.iterations, 6);
  EXPECT_EQ(static_cast<int>(report.trace.size()), report.iterations + 1);
  EXPECT_FALSE(toy.problem.HasManifold(toy.x.data()));

  BoundedToy clipped(Eigen::Vector3d(-1.0, 2.0, 1.0), Eigen::Vector3d(1, 1, 1));
  ceres::Solver::Options options;
  options.function_tolerance = 1e-9;
  options.max_num_line_search_step_size_iterations = 0;
  options.initial_trust_region_radius = kInitialTrustRegionRadius;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &clipped.problem, &summary);
  const double clipped_error =
      (clipped.x.tail<2>() - rest).norm() + std::abs(clipped.x[0]);
  std::printf("active set %d iterations; clipping %d, %.2e from the minimum\n",
              report.iterations,
              static_cast<int>(summary.iterations.size()) - 1, clipped_error);
  EXPECT_GT(clipped_error, 1e-3);
}

// Starting on its bound with the minimum inside (x0 = 0.5): held at
// first, released by its gradient, and the unconstrained minimum reached.
TEST(ActiveBoundsTest, AnEntryTheDataPullOffItsBoundIsReleased) {
  BoundedToy toy(Eigen::Vector3d(0.5, 2.0, 1.0), Eigen::Vector3d(0, 1, 1));
  const SolverReport report = SolveDirect(&toy.problem, SolverOptions());
  EXPECT_TRUE(report.converged) << report.termination;
  EXPECT_NEAR(toy.x[0], 0.5, 1e-6);
  EXPECT_NEAR(toy.x[1], 2.0, 1e-6);
  EXPECT_NEAR(toy.x[2], 1.0, 1e-6);
  EXPECT_FALSE(toy.problem.HasManifold(toy.x.data()));
}

// The set itself: only bounded entries of variable blocks without a
// manifold (the constant block's is not listed); holding and releasing set
// and clear a SubsetManifold.
TEST(ActiveBoundsTest, HoldsAndReleasesThroughASubsetManifold) {
  BoundedToy toy(Eigen::Vector3d(-1.0, 2.0, 1.0), Eigen::Vector3d(0, 1, 1));
  double constant[1] = {0.0};
  toy.problem.AddParameterBlock(constant, 1);
  toy.problem.SetParameterLowerBound(constant, 0, 0.0);
  toy.problem.SetParameterBlockConstant(constant);
  {
    ActiveBounds bounds(&toy.problem);
    ASSERT_FALSE(bounds.empty());
    EXPECT_TRUE(bounds.NewlyActive());
    EXPECT_EQ(bounds.HoldActive(), 1);
    EXPECT_EQ(bounds.held(), 1);
    EXPECT_FALSE(bounds.NewlyActive());
    EXPECT_EQ(toy.problem.ParameterBlockTangentSize(toy.x.data()), 2);
    // The data push x0 below 0 (its minimum is -1): it stays held.
    EXPECT_EQ(bounds.ReleaseInward(), 0);
    EXPECT_EQ(bounds.held(), 1);
  }
  EXPECT_FALSE(toy.problem.HasManifold(toy.x.data()));
  EXPECT_EQ(toy.problem.ParameterBlockTangentSize(toy.x.data()), 3);
}

}  // namespace
}  // namespace pfdm
