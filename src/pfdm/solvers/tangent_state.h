// The explicit integrators' view of a ceres::Problem: its free parameter
// blocks as one tangent vector (docs/dynamics.md), the damping D, the
// stiffest mode's rate, and moves through the blocks' manifolds into their
// bounds.  Shared by forward Euler (dynamics.cc) and RKC (rkc.cc).
#ifndef PFDM_SOLVERS_TANGENT_STATE_H_
#define PFDM_SOLVERS_TANGENT_STATE_H_

#include <optional>
#include <string>
#include <vector>

#include "ceres/crs_matrix.h"
#include "ceres/problem.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// The problem's free parameter blocks and their places in the tangent
// vector that Problem::Evaluate returns.
struct State {
  std::vector<double*> blocks;
  std::vector<int> sizes, offsets;
  int tangent_size = 0;
};

struct Evaluation {
  double cost = 0.0;
  std::vector<double> gradient;
  ceres::CRSMatrix jacobian;
};

State FreeBlocks(const ceres::Problem& problem);
// False if Ceres fails or the cost or gradient is not finite.
bool Evaluate(ceres::Problem* problem, const State& state, int num_threads,
              bool jacobian, Evaluation* evaluation);
double Norm(const std::vector<double>& v);
// D per tangent coordinate (SolverOptions::damping times damping_scale);
// nullopt with *error set for a bad scale.
std::optional<std::vector<double>> Damping(const ceres::Problem& problem,
                                           const State& state,
                                           const ceres::CRSMatrix& j,
                                           const SolverOptions& options,
                                           std::string* error);
// lambda_max of D^-1/2 J^T J D^-1/2 (power iteration; underestimates).
double LargestEigenvalue(const ceres::CRSMatrix& j,
                         const std::vector<double>& d);
bool PlusInBounds(const ceres::Problem& problem, double* block, int size,
                  const double* x, const double* delta, double* out);
// The blocks move by `step` from where they are.
bool Move(ceres::Problem* problem, const State& state,
          const std::vector<double>& step);
// The blocks are set to `base` (a Snapshot) moved by `delta`.
bool Place(ceres::Problem* problem, const State& state,
           const std::vector<double>& base, const std::vector<double>& delta);
double ProjectedGradientNorm(const ceres::Problem& problem, const State& state,
                             const std::vector<double>& gradient);
// Shortens the parts of `delta` (a tangent move from `base`, a Snapshot)
// that would carry a coordinate of a block without a manifold past its
// bounds, so that base [+] delta is where the move ends.
void ClipIntoBounds(const ceres::Problem& problem, const State& state,
                    const std::vector<double>& base,
                    std::vector<double>* delta);
// Zeroes the components of a tangent velocity that push a coordinate of a
// block without a manifold out through the bound it sits on.
void HoldAtBounds(const ceres::Problem& problem, const State& state,
                  std::vector<double>* velocity);
std::vector<double> Snapshot(const State& state);
void Restore(const State& state, const std::vector<double>& values);
void Fail(const std::string& message, SolverReport* report);
// Adds where the integrator is (step `iteration`, pseudo-time `time`) to
// the report's trace, with Ceres' projected gradient norm, and shows it to
// options.on_step.
void RecordStep(const ceres::Problem& problem, const State& state,
                const Evaluation& now, int iteration, double time,
                double wall_seconds, const SolverOptions& options,
                SolverReport* report);

}  // namespace pfdm

#endif  // PFDM_SOLVERS_TANGENT_STATE_H_
