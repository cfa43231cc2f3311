// The three ways pfdm drives a built frame problem to rest: the direct
// Ceres solve, damped stepping inside Ceres, and the explicit Lagrangian
// integrator.  All share the problem's residuals.
#ifndef PFDM_SOLVERS_SOLVER_H_
#define PFDM_SOLVERS_SOLVER_H_

#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ceres/problem.h"
#include "ceres/types.h"

namespace pfdm {

enum class SolverKind { kDirect, kDamped, kIntegrator };

// The integrator's damping matrix D before the per-coordinate scales:
// diag(J^T J) at the start (each parameter moves at the rate the residuals
// hold it, pseudo-time dimensionless), the identity (a constant damping;
// then pseudo-time carries the units of the parameters), or the model's
// coupled damping, J^T J at each step's start (the paper's integral of L^T L
// over the material, sampled at the data, plus the regularizers' block): every
// mode then decays at a rate near 1 (docs/dynamics.md).
enum class DampingKind { kJacobi, kUnit, kModel };

// How the integrator steps D qdot = -J^T r: forward Euler (the paper's
// method) or second-order Runge-Kutta-Chebyshev with error control (the
// same ODE and rest point, a stable step that grows with the square of its
// stage count; docs/dynamics.md).
enum class IntegratorKind { kEuler, kRkc };

// "direct", "damped" or "integrator"; throws InputError otherwise.
SolverKind SolverFromName(const std::string& name);
const char* SolverName(SolverKind kind);
// "jacobi", "unit" or "model"; throws InputError otherwise.
DampingKind DampingFromName(const std::string& name);
const char* DampingName(DampingKind kind);
// "euler" or "rkc"; throws InputError otherwise.
IntegratorKind IntegratorFromName(const std::string& name);
const char* IntegratorName(IntegratorKind kind);

// The direct solve's first trust-region radius: Levenberg-Marquardt
// damping of 1e-8 of the scaled diagonal (see SolveDirect).
constexpr double kInitialTrustRegionRadius = 1e8;

// One iteration (direct, damped) or step (integrator).
struct SolverTracePoint {
  int iteration = 0;
  double pseudo_time = 0.0;  // 0 for the direct solve.
  double wall_seconds = 0.0;
  double cost = 0.0;           // 1/2 sum of squared residuals.
  double gradient_norm = 0.0;  // Projected |J^T r|, as Ceres reports it.
};

struct SolverOptions {
  SolverKind kind = SolverKind::kDirect;
  int max_iterations = 100;
  int num_threads = 1;
  // A frame's global problem has 75-313 parameters whatever its number of
  // points, and the axis gauge ties every knot to every other, so its J^T J
  // is dense: DENSE_SCHUR eliminates one 3-parameter pose block (Ceres'
  // choice) and factorizes the rest with Eigen's blocked dense LLT, built
  // from the same block products as SPARSE_NORMAL_CHOLESKY's J^T J.
  // Eigen's simplicial LDL^T of the same dense matrix, one scalar at a time
  // through its sparse index, took 3x as long: 0.49 against 0.16 s of
  // biv-me patient 1's cavity job, the same 687 iterations
  // (docs/performance.md).  DENSE_NORMAL_CHOLESKY forms the dense Jacobian,
  // a row per point: 1.1 s.
  ceres::LinearSolverType linear_solver = ceres::DENSE_SCHUR;
  // The sparse Cholesky behind SPARSE_NORMAL_CHOLESKY.  Not SuiteSparse:
  // Debian's CHOLMOD runs its supernodal factorization in OpenMP teams of a
  // fixed size (4, whatever OMP_NUM_THREADS says), and on a 2-core machine
  // the caller then waits for threads the scheduler has not run yet: most of
  // a 170-parameter solve's time, spent idle.  Eigen's simplicial LDL^T is
  // single-threaded and does the arithmetic in a fraction of that.
  ceres::SparseLinearAlgebraLibraryType sparse_library = ceres::EIGEN_SPARSE;
  // The residuals are affine in the parameters (the local field's): every
  // solver takes one undamped Gauss-Newton step, the minimum up to
  // round-off.  A linear least-squares problem has one rest point, the
  // same for every damped dynamics, and integrating the field's stiff thin
  // plate to it only costs time; the global functions still follow the
  // chosen dynamics (docs/dynamics.md).
  bool linear = false;
  // Direct only: the bounds an active set (active_bounds.h), not only
  // clipped.  A frame 0 turns it off: it starts far from its minimum, its
  // early steps reach a bound by overshooting, and an entry held there
  // steered the LV wall segment's rounds to a worse fit (frame 0's RMS
  // 0.40 mm against 0.32 on one seed, thickening 3 points apart).
  bool hold_bounds = true;
  // Dynamics (damped and integrator): pseudo-time step, 0 = the default
  // (integrator: 0.9 of the stability bound; damped: 1,000); rest when the
  // energy dissipated per unit pseudo-time falls below rest_tolerance^2 of
  // the initial energy (docs/dynamics.md).
  double time_step = 0.0;
  double rest_tolerance = 1e-6;
  int max_steps = 20000;
  // Integrator only: D = diag(scale) x base.  Per free parameter block, a
  // multiplier for each tangent coordinate (a block not listed: all 1), so
  // that a caller can make parameter groups move at different rates.  The
  // damped mode's D is Ceres' Levenberg-Marquardt diagonal, diag(J^T J).
  // The model damping by default: with it forward Euler rests in 3-11
  // steps a tracked frame; with Jacobi damping it needs about lambda_max /
  // lambda_min (1e4) steps per e-fold of the slowest mode and stops at
  // max_steps short of rest (docs/dynamics.md).
  DampingKind damping = DampingKind::kModel;
  // Integrator only.  Forward Euler by default: with the model damping
  // nothing is stiff and RKC's two stages per step cost 2.4x Euler's
  // evaluations; with Jacobi damping RKC follows the same trajectory in
  // fewer evaluations than Euler.  With RKC, time_step is the first step
  // only.
  IntegratorKind integrator = IntegratorKind::kEuler;
  std::unordered_map<const double*, std::vector<double>> damping_scale;
  // Called with each point of SolverReport::trace as it is recorded, while
  // the parameter blocks hold that iterate: lets a caller keep the path.
  // It may throw to stop the solve (the Python module raises
  // KeyboardInterrupt so): the exception reaches the solver's caller, and
  // the parameter blocks hold some iterate.
  std::function<void(const SolverTracePoint&)> on_step;
  // Called at every iteration of every solver, a refused step's too, and by
  // the fit between its rounds and stages; it may throw to stop the fit
  // (the Python module raises KeyboardInterrupt so, within a step of
  // Ctrl-C).  Unlike on_step, which records the path and which the solves
  // off it (the coarse start, the local field, the verdict's step) clear,
  // nothing clears it.
  std::function<void()> interrupt;
};

// options.interrupt(), where there is one.
inline void CheckInterrupt(const SolverOptions& options) {
  if (options.interrupt) options.interrupt();
}

struct SolverReport {
  int iterations = 0;
  bool usable = true;
  bool converged = false;
  std::string termination;  // e.g. "CONVERGENCE", "NO_CONVERGENCE", "REST".
  std::string message;
  int residual_evaluations = 0;
  int jacobian_evaluations = 0;
  // Evaluating residuals and Jacobians: a speculating solve
  // (PrecomputedGroups) computes a candidate's Jacobians with its residuals.
  double evaluation_seconds = 0.0;
  double linear_solver_seconds = 0.0;
  // Iterating, without the set-up (Ceres' preprocessing) or the summary.
  double minimizer_seconds = 0.0;
  std::vector<SolverTracePoint> trace;
};

// Dispatches on options.kind.
SolverReport SolveProblem(ceres::Problem* problem,
                          const SolverOptions& options);

SolverReport SolveDirect(ceres::Problem* problem, const SolverOptions& options);
SolverReport SolveDamped(ceres::Problem* problem, const SolverOptions& options);
// Dispatches on options.integrator.
SolverReport SolveIntegrator(ceres::Problem* problem,
                             const SolverOptions& options);
SolverReport SolveEuler(ceres::Problem* problem, const SolverOptions& options);
SolverReport SolveRkc(ceres::Problem* problem, const SolverOptions& options);

}  // namespace pfdm

#endif  // PFDM_SOLVERS_SOLVER_H_
