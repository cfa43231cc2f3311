// The paper's mass-free Lagrangian dynamics D qdot = -dE/dq, E = 1/2 |r|^2
// over every residual of the problem (the data springs f_q = -J^T r and the
// stiffness K q of the regularizers alike), integrated two ways; see
// docs/dynamics.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "ceres/crs_matrix.h"
#include "ceres/iteration_callback.h"
#include "ceres/manifold.h"
#include "ceres/solver.h"
#include "pfdm/solver.h"

namespace pfdm {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The problem's free parameter blocks and their places in the tangent
// vector that Problem::Evaluate returns.
struct State {
  std::vector<double*> blocks;
  std::vector<int> sizes, tangent_sizes, offsets;
  int tangent_size = 0;
};

State FreeBlocks(const ceres::Problem& problem) {
  State state;
  std::vector<double*> all;
  problem.GetParameterBlocks(&all);
  for (double* block : all) {
    if (problem.IsParameterBlockConstant(block)) continue;
    state.blocks.push_back(block);
    state.sizes.push_back(problem.ParameterBlockSize(block));
    state.tangent_sizes.push_back(problem.ParameterBlockTangentSize(block));
    state.offsets.push_back(state.tangent_size);
    state.tangent_size += state.tangent_sizes.back();
  }
  return state;
}

struct Evaluation {
  double cost = 0.0;
  std::vector<double> gradient;
  ceres::CRSMatrix jacobian;
};

bool Evaluate(ceres::Problem* problem, const State& state, bool jacobian,
              Evaluation* evaluation) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = state.blocks;
  return problem->Evaluate(options, &evaluation->cost, nullptr,
                           &evaluation->gradient,
                           jacobian ? &evaluation->jacobian : nullptr);
}

double Norm(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

// diag(J^T J), floored so that directions the residuals do not see move
// like weakly damped ones instead of dividing by zero.
std::vector<double> Damping(const ceres::CRSMatrix& j) {
  std::vector<double> d(j.num_cols, 0.0);
  for (size_t k = 0; k < j.values.size(); ++k) {
    d[j.cols[k]] += j.values[k] * j.values[k];
  }
  const double floor =
      1e-12 * std::max(1e-300, *std::max_element(d.begin(), d.end()));
  for (double& x : d) x = std::max(x, floor);
  return d;
}

// Largest eigenvalue of D^-1/2 J^T J D^-1/2 by power iteration: forward
// Euler on D qdot = -J^T J q is stable for dt < 2 / lambda_max.
double LargestEigenvalue(const ceres::CRSMatrix& j,
                         const std::vector<double>& d) {
  std::vector<double> x(j.num_cols, 1.0), y(j.num_rows), z(j.num_cols);
  double lambda = 0.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double norm = Norm(x);
    for (int c = 0; c < j.num_cols; ++c) x[c] /= norm * std::sqrt(d[c]);
    std::fill(y.begin(), y.end(), 0.0);
    for (int r = 0; r < j.num_rows; ++r) {
      for (int k = j.rows[r]; k < j.rows[r + 1]; ++k) {
        y[r] += j.values[k] * x[j.cols[k]];
      }
    }
    std::fill(z.begin(), z.end(), 0.0);
    for (int r = 0; r < j.num_rows; ++r) {
      for (int k = j.rows[r]; k < j.rows[r + 1]; ++k) {
        z[j.cols[k]] += j.values[k] * y[r];
      }
    }
    for (int c = 0; c < j.num_cols; ++c) z[c] /= std::sqrt(d[c]);
    const double next = Norm(z);
    const bool settled = std::abs(next - lambda) < 1e-6 * next;
    lambda = next;
    x = z;
    if (settled) break;
  }
  return lambda;
}

// q <- q [+] step per block, through each block's manifold, then into the
// bounds.  Returns false if a manifold refuses.
bool Move(ceres::Problem* problem, const State& state,
          const std::vector<double>& step) {
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    double* x = state.blocks[b];
    const double* delta = step.data() + state.offsets[b];
    std::vector<double> moved(x, x + state.sizes[b]);
    if (const ceres::Manifold* manifold = problem->GetManifold(x)) {
      if (!manifold->Plus(x, delta, moved.data())) return false;
    } else {
      for (int i = 0; i < state.sizes[b]; ++i) moved[i] += delta[i];
    }
    for (int i = 0; i < state.sizes[b]; ++i) {
      moved[i] = std::clamp(moved[i], problem->GetParameterLowerBound(x, i),
                            problem->GetParameterUpperBound(x, i));
    }
    std::copy(moved.begin(), moved.end(), x);
  }
  return true;
}

std::vector<double> Snapshot(const State& state) {
  std::vector<double> values;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    values.insert(values.end(), state.blocks[b],
                  state.blocks[b] + state.sizes[b]);
  }
  return values;
}

void Restore(const State& state, const std::vector<double>& values) {
  size_t at = 0;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    std::copy(values.begin() + at, values.begin() + at + state.sizes[b],
              state.blocks[b]);
    at += state.sizes[b];
  }
}

// Records the damped trajectory and stops the solve once the model rests.
class RestCallback : public ceres::IterationCallback {
 public:
  RestCallback(double dt, double rest_tolerance, SolverReport* report)
      : dt_(dt), rest_tolerance_(rest_tolerance), report_(report) {}

  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& summary) override {
    report_->trace.push_back({summary.iteration, summary.iteration * dt_,
                              summary.cumulative_time_in_seconds, summary.cost,
                              summary.gradient_norm});
    if (summary.iteration == 0) initial_force_ = summary.gradient_norm;
    if (summary.gradient_norm <= rest_tolerance_ * initial_force_) {
      at_rest_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool at_rest() const { return at_rest_; }

 private:
  double dt_;
  double rest_tolerance_;
  SolverReport* report_;
  double initial_force_ = 0.0;
  bool at_rest_ = false;
};

}  // namespace

// Forward Euler: q_{n+1} = q_n [+] (-dt D^-1 J^T r), D = diag(J^T J) at the
// start, dt = 0.9 x 2 / lambda_max(D^-1/2 J^T J D^-1/2) unless given.  A
// step that raises the cost (the bound was estimated at the start) is
// undone and dt halved.
SolverReport SolveIntegrator(ceres::Problem* problem,
                             const SolverOptions& options) {
  const Clock::time_point start = Clock::now();
  SolverReport report;
  const State state = FreeBlocks(*problem);
  Evaluation now;
  if (!Evaluate(problem, state, true, &now)) {
    report.usable = false;
    report.termination = "FAILURE";
    report.message = "residual evaluation failed at the start";
    return report;
  }
  report.residual_evaluations = report.jacobian_evaluations = 1;
  const std::vector<double> d = Damping(now.jacobian);
  double dt = options.time_step > 0.0
                  ? options.time_step
                  : 0.9 * 2.0 / LargestEigenvalue(now.jacobian, d);
  const double initial_force = Norm(now.gradient);
  double time = 0.0;
  report.trace.push_back({0, 0.0, SecondsSince(start), now.cost, initial_force});
  report.termination = "NO_CONVERGENCE";
  std::vector<double> step(state.tangent_size);
  // Rest: the force has fallen by rest_tolerance, or the cost has stopped
  // falling (relative 1e-12 over a window of steps): the slowest modes of
  // forward Euler decay as (1 - dt lambda_min)^n, and past this point they
  // move the model by less than rounding.
  constexpr int kWindow = 200;
  std::vector<double> costs = {now.cost};
  for (int n = 1; n <= options.max_steps; ++n) {
    const bool stalled =
        costs.size() > kWindow &&
        costs[costs.size() - 1 - kWindow] - now.cost <= 1e-12 * now.cost;
    if (Norm(now.gradient) <= options.rest_tolerance * initial_force ||
        stalled) {
      report.termination = "REST";
      report.converged = true;
      break;
    }
    for (int i = 0; i < state.tangent_size; ++i) {
      step[i] = -dt * now.gradient[i] / d[i];
    }
    const std::vector<double> before = Snapshot(state);
    Evaluation next;
    const bool moved = Move(problem, state, step);
    ++report.residual_evaluations;
    ++report.jacobian_evaluations;
    if (!moved || !Evaluate(problem, state, false, &next) ||
        !std::isfinite(next.cost) || next.cost > now.cost) {
      Restore(state, before);
      dt *= 0.5;
      if (dt < 1e-30) {
        report.usable = false;
        report.termination = "FAILURE";
        report.message = "the integrator cannot take a stable step";
        break;
      }
      continue;
    }
    time += dt;
    now = std::move(next);
    costs.push_back(now.cost);
    report.iterations = n;
    report.trace.push_back(
        {n, time, SecondsSince(start), now.cost, Norm(now.gradient)});
  }
  return report;
}

// Levenberg-Marquardt with the trust region pinned: Ceres solves
// (J^T J + D / radius) dq = -J^T r with D = diag(J^T J) (jacobi scaling
// cancels), the linearly implicit Euler step of D qdot = -J^T r with
// dt = radius.  Held at dt: the radius cannot grow past max, and
// non-monotonic steps keep rejections (which would shrink it) rare.
SolverReport SolveDamped(ceres::Problem* problem, const SolverOptions& options) {
  const double dt = options.time_step > 0.0 ? options.time_step : 100.0;
  SolverReport report;
  RestCallback callback(dt, options.rest_tolerance, &report);
  ceres::Solver::Options solver_options;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.initial_trust_region_radius = dt;
  solver_options.max_trust_region_radius = dt;
  solver_options.use_nonmonotonic_steps = true;
  solver_options.max_consecutive_nonmonotonic_steps =
      std::numeric_limits<int>::max();
  solver_options.linear_solver_type = options.linear_solver;
  solver_options.num_threads = options.num_threads;
  solver_options.max_num_iterations = options.max_steps;
  solver_options.function_tolerance = 0.0;
  solver_options.gradient_tolerance = 0.0;
  solver_options.parameter_tolerance = 1e-14;
  solver_options.logging_type = ceres::SILENT;
  solver_options.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, problem, &summary);

  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  report.usable = summary.IsSolutionUsable() &&
                  summary.termination_type != ceres::FAILURE;
  report.converged = callback.at_rest() ||
                     summary.termination_type == ceres::CONVERGENCE;
  report.termination = callback.at_rest() ? "REST"
                       : ceres::TerminationTypeToString(summary.termination_type);
  report.message = summary.message;
  report.residual_evaluations = summary.num_residual_evaluations;
  report.jacobian_evaluations = summary.num_jacobian_evaluations;
  report.jacobian_seconds = summary.jacobian_evaluation_time_in_seconds;
  report.linear_solver_seconds = summary.linear_solver_time_in_seconds;
  return report;
}

}  // namespace pfdm
