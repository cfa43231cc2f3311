// The paper's mass-free Lagrangian dynamics D qdot = -dE/dq, E = 1/2 |r|^2
// over every residual of the problem (the data springs f_q = -J^T r and the
// stiffness K q of the regularizers alike), integrated two ways; see
// docs/dynamics.md.
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ceres/iteration_callback.h"
#include "ceres/solver.h"
#include "pfdm/solvers/damping_matrix.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/solvers/tangent_state.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// Forward Euler runs at this fraction of its stability limit: the power
// iteration underestimates lambda_max, and at the limit itself the stiffest
// mode would only oscillate.
constexpr double kStabilitySafety = 0.9;
// With the model damping every mode's rate lies in (0, lambda_max] with
// lambda_max about 1: dt = 1 / lambda_max takes the stiffest mode to rest
// in one step and keeps each mode's factor 1 - dt lambda in [0, 1), a
// monotone decay like the continuous dynamics', where 0.9 x 2 / lambda_max
// would flip the sign of the modes near lambda_max at every step.
constexpr double kModelStepFraction = 1.0;
// Pseudo-time step of the damped mode when none is given.  With
// D = diag(J^T J) the explicit limit is about 1; at 1,000 the slow modes of
// a frame fit (lambda ~ 1e-4) lose a tenth or more of their amplitude per
// step and a frame rests in tens of steps.
constexpr double kDefaultDampedStep = 1e3;
// Halvings of an explicit step before the integrator gives up.
constexpr int kMaxRefusals = 50;
// Relative energy changes this small are the rounding of the sum.
constexpr double kRounding = 1e-13;

// Rest: the power the damping dissipates, dE/dt = -qdot^T D qdot =
// -|f|^2_{D^-1}, has fallen below rest_tolerance^2 of the initial energy per
// unit pseudo-time, i.e. the force in the damping metric below
// rest_tolerance of sqrt(E_0).  Measured from the energy itself so that
// both dynamics solvers stop by the same rule, and, unlike |J^T r|, blind
// to forces that a bound holds and to the units of the parameters.
class RestTest {
 public:
  RestTest(double initial_energy, double rest_tolerance)
      : threshold_(rest_tolerance * rest_tolerance * initial_energy) {}
  bool AtRest(double dt, double energy_before, double energy_after) const {
    return std::abs(energy_before - energy_after) <= threshold_ * dt;
  }

 private:
  double threshold_;
};

// Records the damped trajectory and stops the solve once the model rests.
// The step of iteration k was taken with the radius that iteration k - 1
// reported; a rejected step does not move the model and takes no time.
class DampedCallback : public ceres::IterationCallback {
 public:
  DampedCallback(const SolverOptions& options, SolverReport* report)
      : options_(options), report_(report) {}

  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& summary) override {
    try {  // An exception must not unwind through Ceres.
      CheckInterrupt(options_);
    } catch (...) {
      error_ = std::current_exception();
      return ceres::SOLVER_ABORT;
    }
    const double dt = radius_;
    radius_ = summary.trust_region_radius;
    if (summary.iteration == 0) {
      rest_test_.emplace(summary.cost, options_.rest_tolerance);
    } else if (!summary.step_is_successful) {
      return ceres::SOLVER_CONTINUE;
    } else {
      time_ += dt;
    }
    report_->trace.push_back({summary.iteration, time_,
                              summary.cumulative_time_in_seconds, summary.cost,
                              summary.gradient_norm});
    if (options_.on_step) {
      try {  // An exception must not unwind through Ceres.
        options_.on_step(report_->trace.back());
      } catch (...) {
        error_ = std::current_exception();
        return ceres::SOLVER_ABORT;
      }
    }
    const double before = energy_;
    energy_ = summary.cost;
    if (summary.iteration > 0 && rest_test_->AtRest(dt, before, energy_)) {
      at_rest_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool at_rest() const { return at_rest_; }
  // What on_step threw, after the solve.
  void RethrowError() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  const SolverOptions& options_;
  SolverReport* report_;
  std::optional<RestTest> rest_test_;
  double radius_ = 0.0, time_ = 0.0, energy_ = 0.0;
  bool at_rest_ = false;
  std::exception_ptr error_;
};

}  // namespace

// Forward Euler in the tangent space: q_{n+1} = q_n [+] (-dt D^-1 J^T r),
// projected into the bounds.  A step that raises the energy (the stability
// bound was estimated once, at the start) or leaves the residuals
// non-finite is undone and dt halved for good.
SolverReport SolveEuler(ceres::Problem* problem, const SolverOptions& options) {
  const Clock::time_point start = Clock::now();
  CheckInterrupt(options);
  SolverReport report;
  const State state = FreeBlocks(*problem);
  Evaluation now;
  report.residual_evaluations = report.jacobian_evaluations = 1;
  if (!Evaluate(problem, state, options.num_threads, true, &now)) {
    Fail("the residuals or their Jacobian are not finite at the start",
         &report);
    return report;
  }
  const RestTest rest_test(now.cost, options.rest_tolerance);
  std::optional<DampingMatrix> d;
  double dt = options.time_step;
  if (state.tangent_size > 0) {
    std::string error;
    d = DampingMatrix::Build(*problem, state, now.jacobian, options, &error);
    if (!d) {
      Fail(error, &report);
      return report;
    }
    if (dt <= 0.0) {
      dt = (d->diagonal() ? kStabilitySafety * 2.0 : kModelStepFraction) /
           d->LargestRate(now.jacobian);
    }
  }
  now.jacobian = ceres::CRSMatrix();
  double time = 0.0;
  RecordStep(*problem, state, now, 0, 0.0, SecondsSince(start), options,
             &report);
  report.termination = "NO_CONVERGENCE";
  if (state.tangent_size == 0 || Norm(now.gradient) == 0.0) {
    report.termination = "REST";
    report.converged = true;
    return report;
  }
  const double first_dt = dt;
  std::vector<double> velocity, step(state.tangent_size), before;
  Evaluation next;
  int refusals = 0;
  while (report.iterations < options.max_steps) {
    CheckInterrupt(options);  // Refused steps too.
    // A coordinate a bound holds does not move; with a coupled D the others
    // then move by the reduced system, so the model rests where the free
    // force vanishes (for a diagonal D the clipping in Move alone did).
    if (d->diagonal()) {  // Today's arithmetic, to the last bit.
      for (int i = 0; i < state.tangent_size; ++i) {
        step[i] = -dt * now.gradient[i] / d->diagonal_entries()[i];
      }
    } else {
      velocity = d->Velocity(now.gradient,
                             HeldAtBounds(*problem, state, now.gradient));
      for (int i = 0; i < state.tangent_size; ++i) step[i] = dt * velocity[i];
    }
    before = Snapshot(state);
    const bool moved = Move(problem, state, step);
    ++report.residual_evaluations;
    ++report.jacobian_evaluations;
    // The model damping is the paper's D(q) = integral of L(q)^T L(q): taken
    // at the state each step starts from, as an explicit step takes the
    // force (docs/dynamics.md).
    const bool refresh = !d->diagonal();
    const bool finite =
        moved && Evaluate(problem, state, options.num_threads, refresh, &next);
    if (!finite || next.cost > now.cost) {
      Restore(state, before);
      if (finite && next.cost - now.cost <= kRounding * now.cost) {
        report.termination = "REST";  // Flat to rounding: nowhere to go.
        report.converged = true;
        break;
      }
      if (++refusals > kMaxRefusals) {
        Fail(
            "no stable step: the energy rises or the residuals are not "
            "finite even at dt = " +
                std::to_string(dt),
            &report);
        break;
      }
      dt *= 0.5;
      continue;
    }
    refusals = 0;
    time += dt;
    ++report.iterations;
    const bool at_rest = rest_test.AtRest(dt, now.cost, next.cost);
    if (refresh) {
      std::string error;
      std::optional<DampingMatrix> fresh =
          DampingMatrix::Build(*problem, state, next.jacobian, options, &error);
      if (fresh) d = std::move(fresh);  // Else the last D, still SPD.
      next.jacobian = ceres::CRSMatrix();
      // The fresh D's rates are near 1 again: a step halved on the way
      // (a rise where the path curved) grows back toward its start.
      dt = std::min(2.0 * dt, first_dt);
    }
    std::swap(now, next);
    RecordStep(*problem, state, now, report.iterations, time,
               SecondsSince(start), options, &report);
    if (at_rest) {
      report.termination = "REST";
      report.converged = true;
      break;
    }
  }
  report.minimizer_seconds = SecondsSince(start);
  return report;
}

// Levenberg-Marquardt with the trust region pinned at dt: Ceres solves
// (J^T J + diag(J^T J) / radius) dq = -J^T r (Jacobi scaling cancels), the
// linearly implicit Euler step of D qdot = -J^T r with D = diag(J^T J) and
// step radius.  The radius cannot grow past its maximum; a rejected step
// would halve it, so steps are judged against the initial energy
// (unbounded non-monotonic steps) and none is line-searched.
SolverReport SolveDamped(ceres::Problem* problem,
                         const SolverOptions& options) {
  const double dt =
      options.time_step > 0.0 ? options.time_step : kDefaultDampedStep;
  SolverReport report;
  DampedCallback callback(options, &report);
  ceres::Solver::Options solver_options;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.initial_trust_region_radius = dt;
  solver_options.max_trust_region_radius = dt;
  solver_options.min_trust_region_radius = std::min(1e-32, dt);
  solver_options.use_nonmonotonic_steps = true;
  solver_options.max_consecutive_nonmonotonic_steps =
      std::numeric_limits<int>::max();
  solver_options.min_relative_decrease = 0.0;
  solver_options.max_num_line_search_step_size_iterations = 0;
  solver_options.linear_solver_type = options.linear_solver;
  solver_options.sparse_linear_algebra_library_type = options.sparse_library;
  solver_options.num_threads = options.num_threads;
  solver_options.max_num_iterations = options.max_steps;
  // Rest is the callback's to decide; Ceres stops only on a step lost in
  // rounding.
  solver_options.function_tolerance = 0.0;
  solver_options.gradient_tolerance = 0.0;
  solver_options.parameter_tolerance = 1e-15;
  solver_options.logging_type = ceres::SILENT;
  solver_options.callbacks.push_back(&callback);
  solver_options.update_state_every_iteration = bool(options.on_step);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, problem, &summary);
  callback.RethrowError();

  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  report.usable =
      summary.IsSolutionUsable() && summary.termination_type != ceres::FAILURE;
  report.converged =
      callback.at_rest() || summary.termination_type == ceres::CONVERGENCE;
  report.termination =
      callback.at_rest()
          ? "REST"
          : ceres::TerminationTypeToString(summary.termination_type);
  report.message = summary.message;
  report.residual_evaluations = summary.num_residual_evaluations;
  report.jacobian_evaluations = summary.num_jacobian_evaluations;
  report.evaluation_seconds = summary.residual_evaluation_time_in_seconds +
                              summary.jacobian_evaluation_time_in_seconds;
  report.linear_solver_seconds = summary.linear_solver_time_in_seconds;
  report.minimizer_seconds = summary.minimizer_time_in_seconds;
  return report;
}

}  // namespace pfdm
