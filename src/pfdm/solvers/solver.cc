#include "pfdm/solvers/solver.h"

#include <exception>
#include <optional>
#include <utility>

#include "ceres/solver.h"
#include "pfdm/solvers/active_bounds.h"
#include "pfdm/util/error.h"

namespace pfdm {

SolverKind SolverFromName(const std::string& name) {
  if (name == "direct") return SolverKind::kDirect;
  if (name == "damped") return SolverKind::kDamped;
  if (name == "integrator") return SolverKind::kIntegrator;
  throw InputError("unknown --solver '" + name +
                   "' (expected direct, damped or integrator)");
}

const char* SolverName(SolverKind kind) {
  switch (kind) {
    case SolverKind::kDirect:
      return "direct";
    case SolverKind::kDamped:
      return "damped";
    case SolverKind::kIntegrator:
      return "integrator";
  }
  return "";
}

DampingKind DampingFromName(const std::string& name) {
  if (name == "jacobi") return DampingKind::kJacobi;
  if (name == "unit") return DampingKind::kUnit;
  if (name == "model") return DampingKind::kModel;
  throw InputError("unknown --damping '" + name +
                   "' (expected jacobi, unit or model)");
}

const char* DampingName(DampingKind kind) {
  switch (kind) {
    case DampingKind::kJacobi:
      return "jacobi";
    case DampingKind::kUnit:
      return "unit";
    case DampingKind::kModel:
      return "model";
  }
  return "";
}

IntegratorKind IntegratorFromName(const std::string& name) {
  if (name == "euler") return IntegratorKind::kEuler;
  if (name == "rkc") return IntegratorKind::kRkc;
  throw InputError("unknown --integrator '" + name +
                   "' (expected euler or rkc)");
}

const char* IntegratorName(IntegratorKind kind) {
  return kind == IntegratorKind::kEuler ? "euler" : "rkc";
}

SolverReport SolveIntegrator(ceres::Problem* problem,
                             const SolverOptions& options) {
  return options.integrator == IntegratorKind::kEuler
             ? SolveEuler(problem, options)
             : SolveRkc(problem, options);
}

SolverReport SolveProblem(ceres::Problem* problem,
                          const SolverOptions& options) {
  if (options.linear) return SolveDirect(problem, options);
  switch (options.kind) {
    case SolverKind::kDirect:
      return SolveDirect(problem, options);
    case SolverKind::kDamped:
      return SolveDamped(problem, options);
    case SolverKind::kIntegrator:
      return SolveIntegrator(problem, options);
  }
  return {};
}

namespace {

// Hands each iteration to SolverOptions::on_step with the parameter blocks
// at that iterate.  What on_step throws must not unwind through Ceres: it
// is kept, the solve aborted, and rethrown after it.
class StepObserver : public ceres::IterationCallback {
 public:
  explicit StepObserver(const SolverOptions& options) : options_(options) {}
  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& summary) override {
    try {
      CheckInterrupt(options_);
      if (options_.on_step) {
        options_.on_step({summary.iteration, 0.0,
                          summary.cumulative_time_in_seconds, summary.cost,
                          summary.gradient_norm});
      }
    } catch (...) {
      error_ = std::current_exception();
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  void RethrowError() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  const SolverOptions& options_;
  std::exception_ptr error_;
};

// Stops the solve when an entry not held reaches one of its bounds, so
// that it is held there for the rest (ActiveBounds).
class BoundWatcher : public ceres::IterationCallback {
 public:
  explicit BoundWatcher(ActiveBounds* bounds) : bounds_(*bounds) {}
  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary&) override {
    if (!bounds_.NewlyActive()) return ceres::SOLVER_CONTINUE;
    hit_ = true;
    return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }
  bool TakeHit() { return std::exchange(hit_, false); }

 private:
  ActiveBounds& bounds_;
  bool hit_ = false;
};

// Solves at most this many times: holding what became active, releasing
// what the data pull off its bound.
constexpr int kMaxBoundPasses = 6;

ceres::Solver::Options DirectSolverOptions(const SolverOptions& options) {
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = options.linear_solver;
  solver_options.sparse_linear_algebra_library_type = options.sparse_library;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = options.num_threads;
  solver_options.function_tolerance = 1e-9;
  // With bounds Ceres line-searches along every step, bound in sight or
  // not: one more evaluation per iteration (a whole Jacobian with cubic
  // interpolation).  Ours (0 < a <= 1, the exponents' range, h >= 0) are
  // held once active (ActiveBounds), and a step past one is clipped.
  solver_options.max_num_line_search_step_size_iterations = 0;
  solver_options.logging_type = ceres::SILENT;
  // Nearly undamped Gauss-Newton steps from the start (Ceres' default
  // radius, 1e4, damps by 1e-4 of the scaled diagonal).  A fit starts near
  // its minimum (the previous frame's fit, or the previous correspondence
  // round's) where the steps' quality ratio is 1.00; the default damping
  // held back the softest directions (the ring centres' gauge, the partial
  // sums of AxisGaugeChain) for five more iterations, or stopped the solve
  // on the function tolerance short of the minimum.  A step that overshoots
  // is rejected and the radius shrinks as before.
  solver_options.initial_trust_region_radius = kInitialTrustRegionRadius;
  if (options.linear) {
    solver_options.max_num_iterations = 1;
    solver_options.initial_trust_region_radius =
        solver_options.max_trust_region_radius;
  }
  return solver_options;
}

// Adds one Ceres solve to `report`: its iterations after the ones before
// (the trace's start once), its evaluations and times.
void AddSolve(const ceres::Solver::Summary& summary, SolverReport* report) {
  const int first_iteration = report->iterations;
  const double first_second =
      report->trace.empty() ? 0.0 : report->trace.back().wall_seconds;
  for (const ceres::IterationSummary& iteration : summary.iterations) {
    if (!report->trace.empty() && iteration.iteration == 0) continue;
    report->trace.push_back(
        {first_iteration + iteration.iteration, 0.0,
         first_second + iteration.cumulative_time_in_seconds, iteration.cost,
         iteration.gradient_norm});
  }
  report->iterations += static_cast<int>(summary.iterations.size()) - 1;
  report->residual_evaluations += summary.num_residual_evaluations;
  report->jacobian_evaluations += summary.num_jacobian_evaluations;
  report->evaluation_seconds += summary.residual_evaluation_time_in_seconds +
                                summary.jacobian_evaluation_time_in_seconds;
  report->linear_solver_seconds += summary.linear_solver_time_in_seconds;
  report->minimizer_seconds += summary.minimizer_time_in_seconds;
}

// The last solve's outcome.
void SetOutcome(const ceres::Solver::Summary& summary,
                const SolverOptions& options, SolverReport* report) {
  report->usable =
      summary.IsSolutionUsable() && summary.termination_type != ceres::FAILURE;
  report->converged = summary.termination_type == ceres::CONVERGENCE;
  report->termination =
      ceres::TerminationTypeToString(summary.termination_type);
  if (options.linear && report->usable && summary.iterations.size() == 2 &&
      summary.iterations.back().step_is_successful) {
    report->converged = true;  // One exact step is the whole solve.
    report->termination = ceres::TerminationTypeToString(ceres::CONVERGENCE);
  }
  report->message = summary.message;
}

}  // namespace

SolverReport SolveDirect(ceres::Problem* problem,
                         const SolverOptions& options) {
  ceres::Solver::Options solver_options = DirectSolverOptions(options);
  StepObserver observer(options);
  if (options.on_step || options.interrupt) {
    solver_options.callbacks.push_back(&observer);
    solver_options.update_state_every_iteration = bool(options.on_step);
  }
  // Listed only where they are to be held: a linear solve's one step, and
  // frame 0's clipped solves, need no list.
  std::optional<ActiveBounds> bounds;
  std::optional<BoundWatcher> watcher;
  if (options.hold_bounds && !options.linear) bounds.emplace(problem);
  const bool watch = bounds && !bounds->empty();
  if (watch) {
    // The watcher reads the iterate from the parameter blocks.
    solver_options.callbacks.push_back(&watcher.emplace(&*bounds));
    solver_options.update_state_every_iteration = true;
    // Held from the start where the last solve left them (a round after
    // another): a solve stopped at its first iterate costs an evaluation.
    bounds->HoldActive();
  }
  SolverReport report;
  ceres::Solver::Summary summary;
  for (int pass = 0; pass < kMaxBoundPasses; ++pass) {
    if (pass > 0) {
      solver_options.max_num_iterations =
          options.max_iterations - report.iterations;
      if (solver_options.max_num_iterations <= 0) break;
    }
    ceres::Solve(solver_options, problem, &summary);
    observer.RethrowError();
    AddSolve(summary, &report);
    if (!watch) break;
    if (watcher->TakeHit()) {
      if (bounds->HoldActive() > 0) continue;
      solver_options.callbacks.pop_back();  // None to hold: Ceres clips.
      continue;
    }
    if (bounds->held() == 0 || bounds->ReleaseInward() == 0) break;
  }
  SetOutcome(summary, options, &report);
  return report;
}

}  // namespace pfdm
