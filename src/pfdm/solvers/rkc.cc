// The paper's dynamics D qdot = -J^T r by second-order Runge-Kutta-Chebyshev
// with error control (Sommeijer, Shampine & Verwer, J. Comput. Appl. Math.
// 88, 1997; Verwer, Hundsdorfer & Sommeijer, Numer. Math. 57, 1990): an
// explicit method whose s stages are a shifted Chebyshev recursion, stable
// for h lambda in [-beta(s), 0] with beta(s) ~ 0.65 s^2; see
// docs/dynamics.md.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "pfdm/solvers/damping_matrix.h"
#include "pfdm/solvers/rest_estimate.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/solvers/tangent_state.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// The damping epsilon of RKC2: w0 = 1 + epsilon / s^2 keeps |R(z)| <= about
// 1 - epsilon / 3 inside the stable interval, so that stiff modes decay
// instead of ringing, at 2/15 of the undamped interval.
constexpr double kChebyshevDamping = 2.0 / 13.0;
// Stages per step at most: 0.65 x 500^2 / lambda_max of pseudo-time, ~5e4
// on a tracked frame (lambda_max 2.7), against the slowest mode's time
// constant of ~5e3.  The recursion's rounding grows like s^2 x 1e-16.
constexpr int kMaxStages = 500;
// Power iteration underestimates lambda_max; the stage count is chosen for
// this much more.
constexpr double kSpectralMargin = 1.2;
// Local error per step, in the damping metric |e|_D = sqrt(e^T D e) (with
// D = diag(J^T J) the change of the residuals e moves them by, to first
// order), relative to sqrt(E_0): the trajectory is followed to a 1e-4 of
// the initial residual's norm per step.
constexpr double kErrorTolerance = 1e-4;
// Successive refused steps before the solve fails.
constexpr int kMaxRefusals = 50;
// Relative energy rises this small are the rounding of the sum.
constexpr double kRounding = 1e-13;

// The Chebyshev recursion of s stages for an autonomous ODE, indices
// 1..s: Y_1 = Y_0 + mu~_1 h F_0 and
// Y_j = (1 - mu_j - nu_j) Y_0 + mu_j Y_{j-1} + nu_j Y_{j-2}
//       + mu~_j h F(Y_{j-1}) + gamma~_j h F_0.
struct Chebyshev {
  std::vector<double> mu, nu, mu_tilde, gamma_tilde;
  double beta = 0.0;  // Stable for h lambda in [-beta, 0].
};

// T_j, T_j' and T_j'' of the Chebyshev polynomials at w0 by their
// three-term recurrences; b_j = T_j'' / T_j'^2 (b_0 = b_1 = b_2) makes the
// method second order.
Chebyshev ChebyshevOfStages(int s) {
  const double w0 = 1.0 + kChebyshevDamping / (s * s);
  std::vector<double> t(s + 1), dt(s + 1), ddt(s + 1), b(s + 1);
  t[0] = 1.0, t[1] = w0, dt[0] = 0.0, dt[1] = 1.0, ddt[0] = ddt[1] = 0.0;
  for (int j = 2; j <= s; ++j) {
    t[j] = 2.0 * w0 * t[j - 1] - t[j - 2];
    dt[j] = 2.0 * t[j - 1] + 2.0 * w0 * dt[j - 1] - dt[j - 2];
    ddt[j] = 4.0 * dt[j - 1] + 2.0 * w0 * ddt[j - 1] - ddt[j - 2];
    b[j] = ddt[j] / (dt[j] * dt[j]);
  }
  b[0] = b[1] = b[2];
  const double w1 = dt[s] / ddt[s];
  Chebyshev c;
  c.mu.assign(s + 1, 0.0), c.nu.assign(s + 1, 0.0);
  c.mu_tilde.assign(s + 1, 0.0), c.gamma_tilde.assign(s + 1, 0.0);
  c.mu_tilde[1] = b[1] * w1;
  for (int j = 2; j <= s; ++j) {
    c.mu[j] = 2.0 * w0 * b[j] / b[j - 1];
    c.nu[j] = -b[j] / b[j - 2];
    c.mu_tilde[j] = 2.0 * w1 * b[j] / b[j - 1];
    c.gamma_tilde[j] = -(1.0 - b[j - 1] * t[j - 1]) * c.mu_tilde[j];
  }
  c.beta = (1.0 + w0) / w1;
  return c;
}

// The fewest stages (at least 2) whose stable interval holds h rho.
int StagesFor(double h, double rho) {
  int s = std::max(2, 1 + static_cast<int>(std::sqrt(1.0 + 1.54 * h * rho)));
  while (s < kMaxStages && ChebyshevOfStages(s).beta < h * rho) ++s;
  return std::min(s, kMaxStages);
}

// What one RKC step needs and gives: the problem, D and the rate, and per
// step the start (blocks, energy, F_0) and the end (tangent move, F_s).
class RkcStepper {
 public:
  RkcStepper(ceres::Problem* problem, const State& state,
             const SolverOptions& options, DampingMatrix d)
      : problem_(problem), state_(state), options_(options), d_(std::move(d)) {}

  // F = -D^-1 J^T r from an evaluation at the blocks' values, with the
  // coordinates that a bound the model sits on holds left out.
  std::vector<double> Velocity(const Evaluation& e) const {
    return d_.Velocity(e.gradient, HeldAtBounds(*problem_, state_, e.gradient));
  }

  // J^T r at the blocks' values less what a bound holds: the force that is
  // free to move the model.
  std::vector<double> FreeForce(const Evaluation& e) const {
    std::vector<double> g = e.gradient;
    const std::vector<bool> held = HeldAtBounds(*problem_, state_, g);
    for (size_t i = 0; i < g.size(); ++i) {
      if (held[i]) g[i] = 0.0;
    }
    return g;
  }

  // From `base` (a Snapshot, F_0 = f0) one step h of s stages; on success
  // the blocks hold the end, *delta the tangent move and *end its
  // evaluation.  *evaluations counts the problem's evaluations.
  bool Step(const std::vector<double>& base, const std::vector<double>& f0,
            double h, int s, std::vector<double>* delta, Evaluation* end,
            int* evaluations) const {
    const Chebyshev c = ChebyshevOfStages(s);
    const int n = state_.tangent_size;
    std::vector<double> older(n, 0.0), old(n), next(n);
    for (int i = 0; i < n; ++i) old[i] = c.mu_tilde[1] * h * f0[i];
    ClipIntoBounds(*problem_, state_, base, &old);
    Evaluation stage;
    for (int j = 2; j <= s; ++j) {
      ++*evaluations;
      if (!Place(problem_, state_, base, old) ||
          !Evaluate(problem_, state_, options_.num_threads, false, &stage)) {
        return false;
      }
      const std::vector<double> f = Velocity(stage);
      for (int i = 0; i < n; ++i) {
        next[i] = c.mu[j] * old[i] + c.nu[j] * older[i] +
                  h * (c.mu_tilde[j] * f[i] + c.gamma_tilde[j] * f0[i]);
      }
      ClipIntoBounds(*problem_, state_, base, &next);
      older.swap(old);
      old.swap(next);
    }
    ++*evaluations;
    *delta = old;
    return Place(problem_, state_, base, old) &&
           Evaluate(problem_, state_, options_.num_threads, false, end);
  }

  // The embedded estimate of the local error, (12 (y_n - y_{n+1}) +
  // 6 h (F_n + F_{n+1})) / 15, in the damping metric.
  double ErrorNorm(const std::vector<double>& delta,
                   const std::vector<double>& f0, const std::vector<double>& f1,
                   double h) const {
    std::vector<double> est(delta.size());
    for (size_t i = 0; i < delta.size(); ++i) {
      est[i] = (-12.0 * delta[i] + 6.0 * h * (f0[i] + f1[i])) / 15.0;
    }
    return d_.Norm(est);
  }

  const DampingMatrix& d() const { return d_; }

 private:
  ceres::Problem* problem_;
  const State& state_;
  const SolverOptions& options_;
  DampingMatrix d_;
};

// Sommeijer, Shampine & Verwer's step-size rule: after an accepted step
// a second-order predictor from the last two errors, growth at most 10x,
// shrinkage at most 10x.
class StepSizeController {
 public:
  double Accepted(double h, double err) {
    double factor = 10.0;
    if (previous_err_ < 0.0) {
      const double t = std::cbrt(err);
      if (0.8 < factor * t) factor = 0.8 / t;
    } else {
      const double t1 = 0.8 * h * std::cbrt(previous_err_);
      const double t2 = previous_h_ * std::pow(err, 2.0 / 3.0);
      if (t1 < factor * t2) factor = t1 / t2;
    }
    previous_err_ = err, previous_h_ = h;
    return std::max(0.1, factor) * h;
  }
  static double Refused(double h, double err) {
    return std::isfinite(err) && err > 0.0
               ? std::max(0.1, 0.8 / std::cbrt(err)) * h
               : 0.1 * h;
  }

 private:
  double previous_err_ = -1.0, previous_h_ = 0.0;
};

// The step size: error-controlled from 1 / rho (or the given first step),
// or fixed at SolverOptions::time_step, always within kMaxStages' interval.
class StepSize {
 public:
  // With the model damping every rate lies near lambda_max (docs/dynamics.md):
  // nothing is stiff, and a long step of many stages would only damp the
  // modes near its interval's end by |R| ~ 0.95; the step is held at
  // 1 / lambda_max, where two stages' R(-1) = 1/2 is their least.
  StepSize(const SolverOptions& options, double rho, bool diagonal)
      : fixed_(options.time_step > 0.0),
        h_max_(diagonal ? ChebyshevOfStages(kMaxStages).beta / rho
                        : kSpectralMargin / rho),
        h_(std::min(fixed_ ? options.time_step : 1.0 / rho, h_max_)) {}
  double h() const { return h_; }
  bool fixed() const { return fixed_; }
  void Accepted(double err) {
    if (!fixed_) h_ = std::min(controller_.Accepted(h_, err), h_max_);
  }
  // A fixed step that raised the energy is halved for good, as forward
  // Euler's is.
  void Refused(double err, bool rose) {
    h_ = fixed_ || (rose && err <= 1.0) ? 0.5 * h_
                                        : StepSizeController::Refused(h_, err);
  }

 private:
  StepSizeController controller_;
  bool fixed_;
  double h_max_, h_;
};

// The first evaluation, D, rho and the rest estimate; false (report
// failed) if unusable.
bool Start(ceres::Problem* problem, const State& state,
           const SolverOptions& options, Evaluation* now,
           std::optional<DampingMatrix>* d, double* rho,
           std::optional<RestEstimate>* estimate, SolverReport* report) {
  report->residual_evaluations = report->jacobian_evaluations = 1;
  if (!Evaluate(problem, state, options.num_threads, true, now)) {
    Fail("the residuals or their Jacobian are not finite at the start", report);
    return false;
  }
  if (state.tangent_size == 0) return true;
  std::string error;
  *d = DampingMatrix::Build(*problem, state, now->jacobian, options, &error);
  if (!*d) {
    Fail(error, report);
    return false;
  }
  *rho = kSpectralMargin * (*d)->LargestRate(now->jacobian);
  *estimate = RestEstimate::FromJacobian(now->jacobian);
  now->jacobian = ceres::CRSMatrix();
  return true;
}

// The rest rule above SolveRkc, for the free force g and the velocity f at
// the end of a step that moved the model by delta in time h.
bool AtRest(const std::optional<RestEstimate>& estimate,
            const std::vector<double>& g, const std::vector<double>& f,
            const std::vector<double>& delta, const DampingMatrix& d, double h,
            double rest) {
  if (estimate) return estimate->DistanceToRest(g) <= rest;
  return d.Norm(f) <= rest && d.Norm(delta) <= h * rest;
}

}  // namespace

// Rest, as the direct solve judges its own end, by the Gauss-Newton step
// that is left: the residual vector within rest_tolerance x sqrt(E_0) of
// its value at the rest point, sqrt(g^T H^-1 g) with H = J^T J factored at
// the start (RestEstimate; the bound-projected force).  A rule on the force
// alone, |F|_D, fires early along the slowest modes (lambda ~ 1e-3, where
// the distance is 30 times the force) and late along the stiff ones.
// Without an estimate (past RestEstimate::kMaxColumns or H singular) both
// the force and the step's mean velocity, |q_{n+1} - q_n|_D / h, must be
// below that threshold: the force at one point can vanish where the path
// turns, the mean over a step only if the model stood still.
SolverReport SolveRkc(ceres::Problem* problem, const SolverOptions& options) {
  const Clock::time_point start = Clock::now();
  SolverReport report;
  const State state = FreeBlocks(*problem);
  Evaluation now, next;
  std::optional<DampingMatrix> d;
  double rho = 0.0;
  std::optional<RestEstimate> estimate;
  if (!Start(problem, state, options, &now, &d, &rho, &estimate, &report)) {
    return report;
  }
  RecordStep(*problem, state, now, 0, 0.0, SecondsSince(start), options,
             &report);
  if (state.tangent_size == 0 || Norm(now.gradient) == 0.0) {
    report.termination = "REST";
    report.converged = true;
    return report;
  }
  const RkcStepper stepper(problem, state, options, std::move(*d));
  const double scale = std::sqrt(now.cost);
  const double rest = options.rest_tolerance * scale;
  StepSize step_size(options, rho, stepper.d().diagonal());
  double time = 0.0;
  std::vector<double> f0 = stepper.Velocity(now), f1, delta;
  int refusals = 0, evaluations = 0;
  report.termination = "NO_CONVERGENCE";
  while (report.iterations < options.max_steps) {
    const double h = step_size.h();
    const std::vector<double> base = Snapshot(state);
    const bool finite = stepper.Step(base, f0, h, StagesFor(h, rho), &delta,
                                     &next, &evaluations);
    double err = HUGE_VAL;
    if (finite) {
      f1 = stepper.Velocity(next);
      err = stepper.ErrorNorm(delta, f0, f1, h) / (kErrorTolerance * scale);
      if (step_size.fixed()) err = 0.0;
    }
    // Gradient flow loses energy: a rise past rounding is a step off the
    // trajectory (lambda_max underestimated), refused like a large error.
    const bool rose = finite && next.cost > now.cost * (1.0 + kRounding);
    if (!finite || err > 1.0 || rose) {
      Restore(state, base);
      if (++refusals > kMaxRefusals) {
        Fail("no stable RKC step: the error or the energy rises even at h = " +
                 std::to_string(h),
             &report);
        break;
      }
      step_size.Refused(err, rose);
      continue;
    }
    refusals = 0;
    time += h;
    ++report.iterations;
    const bool at_rest = AtRest(estimate, stepper.FreeForce(next), f1, delta,
                                stepper.d(), h, rest);
    std::swap(now, next);
    f0.swap(f1);
    RecordStep(*problem, state, now, report.iterations, time,
               SecondsSince(start), options, &report);
    if (at_rest) {
      report.termination = "REST";
      report.converged = true;
      break;
    }
    step_size.Accepted(err);
  }
  report.residual_evaluations += evaluations;
  report.jacobian_evaluations += evaluations;
  report.minimizer_seconds = SecondsSince(start);
  return report;
}

}  // namespace pfdm
