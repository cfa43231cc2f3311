// The damping matrix D of the paper's dynamics D qdot = -J^T r as the
// explicit integrators apply it: diagonal (Jacobi, unit) or the model's
// coupled damping, a dense SPD matrix (Euler builds it at each step's
// start, RKC once; docs/dynamics.md).
#ifndef PFDM_SOLVERS_DAMPING_MATRIX_H_
#define PFDM_SOLVERS_DAMPING_MATRIX_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "ceres/crs_matrix.h"
#include "ceres/problem.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/solvers/tangent_state.h"

namespace pfdm {

class DampingMatrix {
 public:
  // Above this many tangent coordinates the model damping's dense factor
  // would cost more than the integration (2e8 flops at 1,000): refused.
  static constexpr int kMaxModelColumns = 1000;
  // The model damping's floor, relative to each coordinate's own diagonal
  // entry: keeps D positive definite where J^T J is singular to rounding.
  static constexpr double kModelFloor = 1e-9;

  // D for options.damping from the start's Jacobian, times the caller's
  // per-coordinate scales (S^1/2 D S^1/2); nullopt with *error set for a
  // bad scale or a model damping that cannot be factored.
  static std::optional<DampingMatrix> Build(const ceres::Problem& problem,
                                            const State& state,
                                            const ceres::CRSMatrix& j,
                                            const SolverOptions& options,
                                            std::string* error);
  // A dense D given as is (tests).
  static std::optional<DampingMatrix> FromDense(const Eigen::MatrixXd& d);

  bool diagonal() const { return dense_.size() == 0; }
  // The diagonal (diagonal D only).
  const std::vector<double>& diagonal_entries() const { return diag_; }

  // The velocity f = -D^-1 g with the coordinates in `held` fixed at 0:
  // D_FF f_F = -g_F on the free ones, so that the model stands still
  // exactly where the free force vanishes (a bound's KKT point).
  std::vector<double> Velocity(const std::vector<double>& g,
                               const std::vector<bool>& held) const;
  // D v.
  std::vector<double> Apply(const std::vector<double>& v) const;
  // sqrt(v^T D v).
  double Norm(const std::vector<double>& v) const;
  // lambda_max of D^-1 J^T J by power iteration (underestimates).
  double LargestRate(const ceres::CRSMatrix& j) const;

 private:
  std::vector<double> diag_;
  Eigen::MatrixXd dense_;
  // Of an empty matrix until a dense D is factored: Eigen's default LLT
  // leaves its norm and status unset, which copying a diagonal D read.
  Eigen::LLT<Eigen::MatrixXd> factor_{Eigen::MatrixXd()};
  // D_FF factored per held set: a bound becomes active a few times a solve.
  mutable std::map<std::vector<bool>, Eigen::LLT<Eigen::MatrixXd>> reduced_;
};

// The coordinates of blocks without a manifold that sit on a bound the
// force g pushes them through (-g points outward).
std::vector<bool> HeldAtBounds(const ceres::Problem& problem,
                               const State& state,
                               const std::vector<double>& g);

}  // namespace pfdm

#endif  // PFDM_SOLVERS_DAMPING_MATRIX_H_
