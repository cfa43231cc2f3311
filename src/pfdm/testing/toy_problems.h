// Small least-squares problems with known minima, shared by the solvers'
// tests, and the set-up each test starts from: the parameters, the problem
// that holds them and the options of the solver under test.
#ifndef PFDM_TESTING_TOY_PROBLEMS_H_
#define PFDM_TESTING_TOY_PROBLEMS_H_

#include <cmath>

#include "Eigen/Dense"
#include "ceres/autodiff_cost_function.h"
#include "ceres/problem.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// r = J x - b with J = (1 0; 0 10; 0.1 0.1), b = (1, 20, 0.3): minimum at
// (1, 2) with r = 0, stiff in x1 and soft in x0 as the model's parameters
// are.
struct LinearResidual {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] - 1.0;
    r[1] = 10.0 * (x[1] - 2.0);
    r[2] = 0.1 * (x[0] + x[1] - 3.0);
    return true;
  }
};

inline Eigen::Matrix<double, 3, 2> LinearJacobian() {
  return (Eigen::Matrix<double, 3, 2>() << 1, 0, 0, 10, 0.1, 0.1).finished();
}

inline Eigen::Vector2d LinearGradient(const Eigen::Vector2d& x) {
  const Eigen::Vector3d b(1.0, 20.0, 0.3);
  return LinearJacobian().transpose() * (LinearJacobian() * x - b);
}

inline void AddLinear(ceres::Problem* problem, double* x) {
  problem->AddResidualBlock(
      new ceres::AutoDiffCostFunction<LinearResidual, 3, 2>(new LinearResidual),
      nullptr, x);
}

// Forward Euler's limit 2 / lambda_max(D^-1/2 J^T J D^-1/2), D = diag(J^T J).
inline double LinearStabilityBound() {
  const Eigen::Matrix2d h = LinearJacobian().transpose() * LinearJacobian();
  const Eigen::Vector2d s = h.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::Matrix2d a = s.asDiagonal() * h * s.asDiagonal();
  return 2.0 / Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(a)
                   .eigenvalues()
                   .maxCoeff();
}

// r = x^2 - 4: minimum at x = 2 from any x > 0.
struct QuadraticResidual {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] * x[0] - 4.0;
    return true;
  }
};

// r = sqrt(x) - 1: NaN for x < 0, which a long step reaches.
struct SquareRootResidual {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = sqrt(x[0]) - 1.0;
    return true;
  }
};

// kSize parameters x, the problem over them and options for the solver
// under test.  Not copied: the problem points into x.
template <int kSize>
struct ToyProblem {
  explicit ToyProblem(SolverKind kind) { options.kind = kind; }
  ToyProblem(const ToyProblem&) = delete;
  ToyProblem& operator=(const ToyProblem&) = delete;

  SolverReport Solve() { return SolveProblem(&problem, options); }

  double x[kSize];
  ceres::Problem problem;
  SolverOptions options;
};

// LinearResidual from x = (5, -3).
struct LinearToyProblem : ToyProblem<2> {
  explicit LinearToyProblem(SolverKind kind) : ToyProblem<2>(kind) {
    x[0] = 5.0;
    x[1] = -3.0;
    AddLinear(&problem, x);
  }
};

// Residual, one residual of the one parameter, from x = start.
template <typename Residual>
struct ScalarToyProblem : ToyProblem<1> {
  ScalarToyProblem(double start, SolverKind kind) : ToyProblem<1>(kind) {
    x[0] = start;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Residual, 1, 1>(new Residual), nullptr,
        x);
  }
};

}  // namespace pfdm

#endif  // PFDM_TESTING_TOY_PROBLEMS_H_
