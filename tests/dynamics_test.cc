#include <cmath>
#include <memory>

#include "ceres/autodiff_cost_function.h"
#include "ceres/manifold.h"
#include "ceres/problem.h"
#include "ceres/rotation.h"
#include "gtest/gtest.h"
#include "pfdm/fitter.h"
#include "pfdm/phantom.h"
#include "pfdm/solver.h"

namespace pfdm {
namespace {

// r = (x0 - 1, 10 (x1 - 2), 0.1 (x0 + x1 - 3)): minimum at (1, 2), stiff in
// x1 and soft in x0, as the model's parameters are.
struct Linear {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] - 1.0;
    r[1] = 10.0 * (x[1] - 2.0);
    r[2] = 0.1 * (x[0] + x[1] - 3.0);
    return true;
  }
};

void AddLinear(ceres::Problem* problem, double* x) {
  problem->AddResidualBlock(
      new ceres::AutoDiffCostFunction<Linear, 3, 2>(new Linear), nullptr, x);
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

class SolverKindTest : public ::testing::TestWithParam<SolverKind> {};

TEST_P(SolverKindTest, ReachesTheMinimumOfALinearProblem) {
  double x[2] = {5.0, -3.0};
  ceres::Problem problem;
  AddLinear(&problem, x);
  SolverOptions options;
  options.kind = GetParam();
  options.max_steps = 100000;
  options.rest_tolerance = 1e-12;
  const SolverReport report = SolveProblem(&problem, options);
  EXPECT_TRUE(report.usable);
  EXPECT_NEAR(x[0], 1.0, 1e-5) << SolverName(GetParam());
  EXPECT_NEAR(x[1], 2.0, 1e-6) << SolverName(GetParam());
  ASSERT_GE(report.trace.size(), 2u);
  for (size_t i = 1; i < report.trace.size(); ++i) {
    EXPECT_GE(report.trace[i].pseudo_time, report.trace[i - 1].pseudo_time);
    EXPECT_LE(report.trace[i].cost, report.trace[i - 1].cost * (1 + 1e-12));
  }
}

TEST_P(SolverKindTest, FollowsTheQuaternionManifoldAndBounds) {
  double q[4] = {1.0, 0.0, 0.0, 0.0};
  double x[2] = {5.0, -3.0};
  ceres::Problem problem;
  AddRotation(&problem, q);
  AddLinear(&problem, x);
  problem.SetParameterUpperBound(x, 0, 0.5);  // The minimum lies beyond.
  SolverOptions options;
  options.kind = GetParam();
  options.max_steps = 100000;
  SolveProblem(&problem, options);
  EXPECT_NEAR(std::hypot(std::hypot(q[0], q[1]), std::hypot(q[2], q[3])), 1.0,
              1e-12);
  // Ceres' own convergence test stops the direct solve near 1e-4 here.
  EXPECT_NEAR(2.0 * std::atan2(q[3], q[0]), 0.5, 1e-3) << SolverName(GetParam());
  EXPECT_NEAR(x[0], 0.5, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolverKindTest,
                         ::testing::Values(SolverKind::kDirect,
                                           SolverKind::kDamped,
                                           SolverKind::kIntegrator));

// Forward Euler past 2 / lambda_max diverges; the integrator must refuse
// such steps (halving dt) rather than blow up.
TEST(IntegratorTest, RefusesStepsAboveTheStabilityBound) {
  double x[2] = {5.0, -3.0};
  ceres::Problem problem;
  AddLinear(&problem, x);
  SolverOptions options;
  options.kind = SolverKind::kIntegrator;
  // With D = diag(J^T J) the preconditioned system's largest eigenvalue is
  // about 1, so the bound is about 2.
  options.time_step = 5.0;
  options.max_steps = 100000;
  options.rest_tolerance = 1e-12;
  const SolverReport report = SolveProblem(&problem, options);
  EXPECT_TRUE(report.usable);
  EXPECT_NEAR(x[1], 2.0, 1e-6);
  ASSERT_GE(report.trace.size(), 2u);
  EXPECT_LT(report.trace[1].pseudo_time, 2.5);
}

TEST(DampedTest, PseudoTimeAdvancesByTheFixedStep) {
  double x[2] = {5.0, -3.0};
  ceres::Problem problem;
  AddLinear(&problem, x);
  SolverOptions options;
  options.kind = SolverKind::kDamped;
  options.time_step = 0.5;
  const SolverReport report = SolveProblem(&problem, options);
  ASSERT_GE(report.trace.size(), 3u);
  EXPECT_DOUBLE_EQ(report.trace[2].pseudo_time, 1.0);
  EXPECT_EQ(report.termination, "REST");
}

// The paper's dynamic fit and the direct least-squares solve of the same
// residuals end at the same model: functions within 0.01 mm and 0.01
// degree, RMS within 1 %, on a small phantom (300 tags, 9 knots).
TEST(DynamicsTest, AllThreeSolversReachTheSameFixedPoint) {
  PhantomOptions phantom_options;
  phantom_options.num_points = 300;
  phantom_options.num_frames = 2;
  phantom_options.num_knots = 9;
  const Phantom phantom = MakePhantom(phantom_options);
  SequenceFit fits[3];
  int i = 0;
  for (SolverKind kind : {SolverKind::kDirect, SolverKind::kDamped,
                          SolverKind::kIntegrator}) {
    FitOptions options;
    options.solver.kind = kind;
    fits[i++] = FitSequence(phantom.points, ModelConfig::Paper(9), options);
  }
  const KnotGrid grid = fits[0].config.Grid();
  for (int s = 1; s < 3; ++s) {
    for (size_t t = 0; t < 2; ++t) {
      const Model direct = fits[0].ModelAt(t), other = fits[s].ModelAt(t);
      EXPECT_NEAR(fits[s].frames[t].rms_mm / fits[0].frames[t].rms_mm, 1.0,
                  0.01);
      const double a0 = direct.state.globals[kA0];
      EXPECT_NEAR(other.state.globals[kA0], a0, 0.01);
      for (int k = 0; k < grid.num_knots(); ++k) {
        const double u = grid.KnotU(k);
        for (int f : {kA1, kA2, kA3}) {
          EXPECT_NEAR(a0 * other.FunctionAt(f, u), a0 * direct.FunctionAt(f, u),
                      0.01)
              << "solver " << s << " frame " << t << " knot " << k;
        }
        for (int f : {kE1o, kE2o, kB0, kB2}) {
          EXPECT_NEAR(other.FunctionAt(f, u), direct.FunctionAt(f, u), 0.01);
        }
        EXPECT_NEAR(other.FunctionAt(kTau, u), direct.FunctionAt(kTau, u),
                    0.01 * M_PI / 180);
      }
    }
  }
}

}  // namespace
}  // namespace pfdm
