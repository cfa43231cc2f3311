// Runge-Kutta-Chebyshev (IntegratorKind::kRkc) against forward Euler on a
// stiff linear system whose modes are known: uncoupled, rates 1e-3 to 10
// (the stiffness ratio of a frame fit, docs/dynamics.md), so that every
// mode's exact path is x_i(t) = c_i (1 - exp(-lambda_i t)).
#include <cmath>
#include <vector>

#include "ceres/problem.h"
#include "ceres/sized_cost_function.h"
#include "gtest/gtest.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {
namespace {

// r = sqrt(lambda) (x - c): with unit damping, x' = -lambda (x - c).
class DiagonalResidual : public ceres::SizedCostFunction<1, 1> {
 public:
  DiagonalResidual(double lambda, double c) : root_(std::sqrt(lambda)), c_(c) {}
  bool Evaluate(double const* const* x, double* r,
                double** jacobians) const override {
    r[0] = root_ * (x[0][0] - c_);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      jacobians[0][0] = root_;
    }
    return true;
  }

 private:
  double root_, c_;
};

constexpr int kModes = 20;

struct StiffToy {
  explicit StiffToy(IntegratorKind integrator) {
    options.kind = SolverKind::kIntegrator;
    options.integrator = integrator;
    options.damping = DampingKind::kUnit;
    for (int i = 0; i < kModes; ++i) {
      lambda[i] = std::pow(10.0, -3.0 + 4.0 * i / (kModes - 1));
      x[i] = 0.0;
      problem.AddResidualBlock(new DiagonalResidual(lambda[i], Target(i)),
                               nullptr, &x[i]);
    }
  }
  static double Target(int i) { return 1.0 + i; }
  // max_i |x_i - c_i|.
  double LargestError() const {
    double largest = 0.0;
    for (int i = 0; i < kModes; ++i) {
      largest = std::max(largest, std::abs(x[i] - Target(i)));
    }
    return largest;
  }
  SolverReport Solve() { return SolveProblem(&problem, options); }

  double x[kModes], lambda[kModes];
  ceres::Problem problem;
  SolverOptions options;
};

// Forward Euler needs about lambda_max / lambda_min steps per e-fold of the
// slowest mode (here 1e4 / 1.8); RKC's stable step grows with the square
// of its stages, and its error-controlled steps grow as the model settles.
// The two rest rules differ: Euler's force below 1e-8 sqrt(E_0) leaves
// the slowest mode up to 1e-8 / sqrt(1e-3) = 3e-7 sqrt(E_0) from rest in
// the residuals: RKC's rule (the distance itself) is given that.  (At 1e-8
// RKC took 53,090 evaluations; at 1e-6 its slowest mode was 1.1e-3 off.)
TEST(RkcTest, RestsAtTheMinimumInAFractionOfEulersEvaluations) {
  StiffToy euler(IntegratorKind::kEuler), rkc(IntegratorKind::kRkc);
  for (StiffToy* toy : {&euler, &rkc}) {
    toy->options.rest_tolerance = 1e-8;
    toy->options.max_steps = 1000000;
  }
  rkc.options.rest_tolerance = 3e-7;
  const SolverReport euler_report = euler.Solve();
  const SolverReport rkc_report = rkc.Solve();
  EXPECT_EQ(euler_report.termination, "REST");
  EXPECT_EQ(rkc_report.termination, "REST");
  // Both rules stop on the force (below 1e-8 sqrt(E_0)), which leaves the
  // slowest mode up to 1e-8 x 67 / 1e-3 away.
  EXPECT_LT(euler.LargestError(), 1e-3);
  EXPECT_LT(rkc.LargestError(), 1e-3);
  EXPECT_LT(10 * rkc_report.jacobian_evaluations,
            euler_report.jacobian_evaluations);
  EXPECT_EQ(rkc_report.jacobian_evaluations, rkc_report.residual_evaluations);
}

// The error-controlled path stays on the exact one: at every step, in the
// damping metric (here |e|_D = sqrt(sum lambda_i e_i^2), how far the
// residuals are from the exact path's), within 1e-3 of sqrt(E_0) (the
// local tolerance is 1e-4 per step).
TEST(RkcTest, FollowsTheExactTrajectory) {
  StiffToy rkc(IntegratorKind::kRkc);
  double worst = 0.0, energy0 = -1.0;
  int points = 0;
  rkc.options.on_step = [&](const SolverTracePoint& point) {
    if (energy0 < 0.0) energy0 = point.cost;
    double sum = 0.0;
    for (int i = 0; i < kModes; ++i) {
      const double exact = StiffToy::Target(i) *
                           (1.0 - std::exp(-rkc.lambda[i] * point.pseudo_time));
      sum += rkc.lambda[i] * std::pow(rkc.x[i] - exact, 2);
    }
    worst = std::max(worst, std::sqrt(sum / energy0));
    ++points;
  };
  const SolverReport report = rkc.Solve();
  EXPECT_EQ(report.termination, "REST");
  EXPECT_GT(points, 10);
  EXPECT_LT(worst, 1e-3);
}

// At a fixed step h = 1, five times forward Euler's limit 2 / lambda_max:
// Euler's step multiplies the stiffest mode by 1 - 10 = -9, raises the
// energy and is refused, three times, before h / 8 is stable.  RKC takes
// every step at h (stages chosen for 1.2 lambda_max h), the energy never
// rises and every mode decays.
TEST(RkcTest, TakesStableStepsWhereForwardEulerDiverges) {
  StiffToy euler(IntegratorKind::kEuler), rkc(IntegratorKind::kRkc);
  for (StiffToy* toy : {&euler, &rkc}) {
    toy->options.time_step = 1.0;
    toy->options.max_steps = 40;
  }
  const SolverReport euler_report = euler.Solve();
  ASSERT_GE(euler_report.trace.size(), 2u);
  EXPECT_DOUBLE_EQ(euler_report.trace[1].pseudo_time, 1.0 / 8);
  EXPECT_EQ(euler_report.residual_evaluations, euler_report.iterations + 4);

  const SolverReport rkc_report = rkc.Solve();
  ASSERT_EQ(rkc_report.iterations, 40);
  for (size_t i = 1; i < rkc_report.trace.size(); ++i) {
    EXPECT_DOUBLE_EQ(rkc_report.trace[i].pseudo_time, i * 1.0);
    EXPECT_LE(rkc_report.trace[i].cost, rkc_report.trace[i - 1].cost);
  }
  for (int i = 0; i < kModes; ++i) {
    const double error = std::abs(rkc.x[i] - StiffToy::Target(i));
    EXPECT_LT(error, StiffToy::Target(i)) << "mode " << i;
    // The fast modes (lambda >= 0.1, 4 e-folds in 40) are gone.
    if (rkc.lambda[i] >= 0.1) {
      EXPECT_LT(error, 0.05 * StiffToy::Target(i)) << "mode " << i;
    }
  }
}

}  // namespace
}  // namespace pfdm
