#include "pfdm/solvers/solver.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "ceres/autodiff_cost_function.h"
#include "ceres/manifold.h"
#include "ceres/problem.h"
#include "ceres/rotation.h"
#include "gtest/gtest.h"
#include "pfdm/testing/toy_problems.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

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
  ScalarToyProblem<QuadraticResidual> toy(5.0, SolverKind::kDirect);
  const SolverReport report = SolveDirect(&toy.problem, SolverOptions());
  EXPECT_NEAR(toy.x[0], 2.0, 1e-8);
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
  ScalarToyProblem<QuadraticResidual> toy(
      std::numeric_limits<double>::quiet_NaN(), SolverKind::kDirect);
  const SolverReport report = SolveDirect(&toy.problem, SolverOptions());
  EXPECT_FALSE(report.usable);
  EXPECT_EQ(report.termination, "FAILURE");
  EXPECT_FALSE(report.message.empty());
}

// Each kind reaches x = 2 its own way: the dynamics in pseudo-time, the
// integrator with one evaluation per step.
TEST(SolverTest, SolveProblemDispatchesOnTheKind) {
  for (SolverKind kind :
       {SolverKind::kDirect, SolverKind::kDamped, SolverKind::kIntegrator}) {
    ScalarToyProblem<QuadraticResidual> toy(5.0, kind);
    const SolverReport report = toy.Solve();
    EXPECT_NEAR(toy.x[0], 2.0, 1e-5) << SolverName(kind);
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

// A linear problem (the local field's) has one rest point, the least-squares
// solution: every kind takes the direct solve's one Gauss-Newton step to it
// (no pseudo-time), to 1e-10 of LinearGradient's zero.
TEST(SolverTest, ALinearProblemIsSolvedDirectlyByEveryKind) {
  for (SolverKind kind :
       {SolverKind::kDirect, SolverKind::kDamped, SolverKind::kIntegrator}) {
    LinearToyProblem toy(kind);
    toy.options.linear = true;
    const SolverReport report = toy.Solve();
    SCOPED_TRACE(SolverName(kind));
    EXPECT_EQ(report.termination, "CONVERGENCE");
    EXPECT_EQ(report.iterations, 1);
    EXPECT_EQ(report.trace.back().pseudo_time, 0.0);
    EXPECT_LT(LinearGradient(Eigen::Vector2d(toy.x[0], toy.x[1])).norm(),
              1e-10);
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
    ScalarToyProblem<QuadraticResidual> toy(5.0, kind);
    int steps = 0;
    toy.options.on_step = [&steps](const SolverTracePoint& point) {
      ++steps;
      if (point.iteration == 1) throw Stop{point.iteration};
    };
    try {
      toy.Solve();
      ADD_FAILURE() << SolverName(kind) << " finished";
    } catch (const Stop& stop) {
      EXPECT_EQ(stop.iteration, 1) << SolverName(kind);
    }
    EXPECT_EQ(steps, 2) << SolverName(kind);
    // Not solved.
    EXPECT_GT(std::abs(toy.x[0] - 2.0), 1e-3) << SolverName(kind);
  }
}

// Rotates three points onto their images: the rotation is the known 0.5
// rad about z; the quaternion lives on the QuaternionManifold.
struct Rotated {
  Eigen::Vector3d point, image;
  template <typename T>
  bool operator()(const T* q, T* r) const {
    const T p[3] = {T(point.x()), T(point.y()), T(point.z())};
    T x[3];
    ceres::UnitQuaternionRotatePoint(q, p, x);
    for (int i = 0; i < 3; ++i) r[i] = x[i] - image[i];
    return true;
  }
};

void AddRotation(ceres::Problem* problem, double* q) {
  const double c = std::cos(0.5), s = std::sin(0.5);
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 2, 0),
        Eigen::Vector3d(1, 1, 1)}) {
    const Eigen::Vector3d image(c * p.x() - s * p.y(), s * p.x() + c * p.y(),
                                p.z());
    problem->AddResidualBlock(
        new ceres::AutoDiffCostFunction<Rotated, 3, 4>(new Rotated{p, image}),
        nullptr, q);
  }
  problem->SetManifold(q, new ceres::QuaternionManifold);
}

void ExpectTimeAdvances(const SolverReport& report) {
  ASSERT_GE(report.trace.size(), 2u);
  for (size_t i = 1; i < report.trace.size(); ++i) {
    EXPECT_GT(report.trace[i].iteration, report.trace[i - 1].iteration);
    EXPECT_GE(report.trace[i].wall_seconds, report.trace[i - 1].wall_seconds);
    if (report.trace[i].pseudo_time != 0.0) {
      EXPECT_GT(report.trace[i].pseudo_time, report.trace[i - 1].pseudo_time);
    }
  }
}

// What every kind of solve does alike, run once per kind.
class SolverKindTest : public ::testing::TestWithParam<SolverKind> {};

TEST_P(SolverKindTest, ReachesTheMinimumOfALinearProblem) {
  LinearToyProblem toy(GetParam());
  toy.options.rest_tolerance = 1e-9;
  const SolverReport report = toy.Solve();
  EXPECT_TRUE(report.usable);
  EXPECT_TRUE(report.converged) << report.termination;
  EXPECT_NEAR(toy.x[0], 1.0, 1e-6);
  EXPECT_NEAR(toy.x[1], 2.0, 1e-7);
  ExpectTimeAdvances(report);
  // Gradient flow, explicit or implicit, only loses energy on a quadratic.
  for (size_t i = 1; i < report.trace.size(); ++i) {
    EXPECT_LE(report.trace[i].cost, report.trace[i - 1].cost);
  }
  if (GetParam() != SolverKind::kDirect) {
    EXPECT_EQ(report.termination, "REST");
    EXPECT_GT(report.trace.back().pseudo_time, 0.0);
  }
}

// on_step sees every trace point with the parameters at that iterate: the
// cost recomputed from them is the cost the trace reports.
TEST_P(SolverKindTest, OnStepSeesEachIterate) {
  LinearToyProblem toy(GetParam());
  std::vector<SolverTracePoint> seen;
  std::vector<double> costs;
  toy.options.on_step = [&](const SolverTracePoint& point) {
    seen.push_back(point);
    const Eigen::Vector3d r =
        LinearJacobian() * Eigen::Vector2d(toy.x[0], toy.x[1]) -
        Eigen::Vector3d(1.0, 20.0, 0.3);
    costs.push_back(0.5 * r.squaredNorm());
  };
  const SolverReport report = toy.Solve();
  ASSERT_EQ(seen.size(), report.trace.size());
  ASSERT_GE(seen.size(), 2u);
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].iteration, report.trace[i].iteration);
    EXPECT_NEAR(costs[i], report.trace[i].cost,
                1e-12 * (1.0 + report.trace[i].cost))
        << "point " << i;
  }
  EXPECT_GT(costs.front(), 100.0 * costs.back() + 1e-12);
}

// The rotation is reached on the unit sphere and x0 stops at its bound.
// Ceres (direct, damped) solves each step as if unbounded and then clips
// it, so x1, coupled to x0, stops short of the constrained minimum
// (ceres-solver issue 187); the integrator's projected gradient flow
// reaches it, and the bound's reaction is no force in its trace.
TEST_P(SolverKindTest, FollowsTheQuaternionManifoldAndBounds) {
  double q[4] = {1.0, 0.0, 0.0, 0.0};
  double x[2] = {5.0, -3.0};
  ceres::Problem problem;
  AddRotation(&problem, q);
  AddLinear(&problem, x);
  problem.SetParameterUpperBound(x, 0, 0.5);  // The minimum lies beyond.
  SolverOptions options;
  options.kind = GetParam();
  options.rest_tolerance = 1e-9;
  const SolverReport report = SolveProblem(&problem, options);
  EXPECT_TRUE(report.converged) << report.termination;
  EXPECT_NEAR(std::hypot(std::hypot(q[0], q[1]), std::hypot(q[2], q[3])), 1.0,
              1e-12);
  // Ceres' own function tolerance stops the direct solve near 1e-4 here.
  EXPECT_NEAR(2.0 * std::atan2(q[3], q[0]), 0.5, 1e-3);
  EXPECT_EQ(x[0], 0.5);
  // d/dx1 of 50 (x1 - 2)^2 + 0.005 (x1 - 2.5)^2 = 0.
  const double x1 = (100.0 * 2.0 + 0.01 * 2.5) / 100.01;
  EXPECT_NEAR(x[1], x1, 1e-4);
  if (GetParam() == SolverKind::kIntegrator) {
    EXPECT_NEAR(x[1], x1, 1e-8);
    EXPECT_GT(LinearGradient({x[0], x[1]}).norm(), 0.4);
    EXPECT_LT(report.trace.back().gradient_norm, 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolverKindTest,
                         ::testing::Values(SolverKind::kDirect,
                                           SolverKind::kDamped,
                                           SolverKind::kIntegrator),
                         [](const auto& info) {
                           return std::string(SolverName(info.param));
                         });

}  // namespace
}  // namespace pfdm
