// The integrators' damping matrix; see damping_matrix.h.
#include "pfdm/solvers/damping_matrix.h"

#include <algorithm>
#include <cmath>

#include "pfdm/solvers/normal_matrix.h"

namespace pfdm {
namespace {

Eigen::VectorXd AsEigen(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(),
                                           static_cast<Eigen::Index>(v.size()));
}

std::vector<double> AsVector(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

}  // namespace

// The model damping is J^T J of the start, floored on its diagonal: the
// data's block is the paper's integral of L^T L over the model's material,
// sampled at the data's material points, and the regularizers' block is
// their stiffness' Gauss-Newton matrix (docs/dynamics.md).  The scales
// enter symmetrically so that D stays symmetric.
std::optional<DampingMatrix> DampingMatrix::Build(const ceres::Problem& problem,
                                                  const State& state,
                                                  const ceres::CRSMatrix& j,
                                                  const SolverOptions& options,
                                                  std::string* error) {
  if (options.damping != DampingKind::kModel) {
    std::optional<std::vector<double>> d =
        Damping(problem, state, j, options, error);
    if (!d) return std::nullopt;
    DampingMatrix damping;
    damping.diag_ = std::move(*d);
    return damping;
  }
  if (j.num_cols > kMaxModelColumns) {
    *error = "the model damping is dense: " + std::to_string(j.num_cols) +
             " parameters, more than " + std::to_string(kMaxModelColumns);
    return std::nullopt;
  }
  SolverOptions unit = options;
  unit.damping = DampingKind::kUnit;
  const std::optional<std::vector<double>> scale =
      Damping(problem, state, j, unit, error);
  if (!scale) return std::nullopt;
  Eigen::MatrixXd d = GaussNewtonMatrix(j);
  const double largest = d.diagonal().maxCoeff();
  for (int c = 0; c < d.rows(); ++c) {
    d(c, c) +=
        std::max(kModelFloor * d(c, c), 1e-12 * std::max(largest, 1e-300));
  }
  const Eigen::VectorXd root = AsEigen(*scale).cwiseSqrt();
  std::optional<DampingMatrix> damping =
      FromDense(root.asDiagonal() * d * root.asDiagonal());
  if (!damping) *error = "the model damping is not positive definite";
  return damping;
}

std::optional<DampingMatrix> DampingMatrix::FromDense(
    const Eigen::MatrixXd& d) {
  DampingMatrix damping;
  damping.dense_ = d;
  damping.factor_.compute(d);
  if (d.size() == 0 || damping.factor_.info() != Eigen::Success) {
    return std::nullopt;
  }
  return damping;
}

std::vector<double> DampingMatrix::Velocity(
    const std::vector<double>& g, const std::vector<bool>& held) const {
  const int n = static_cast<int>(g.size());
  std::vector<double> f(n, 0.0);
  if (diagonal()) {
    for (int i = 0; i < n; ++i) f[i] = held[i] ? 0.0 : -g[i] / diag_[i];
    return f;
  }
  if (std::find(held.begin(), held.end(), true) == held.end()) {
    return AsVector(-factor_.solve(AsEigen(g)));
  }
  std::vector<int> free;
  for (int i = 0; i < n; ++i) {
    if (!held[i]) free.push_back(i);
  }
  const int m = static_cast<int>(free.size());
  auto reduced = reduced_.find(held);
  if (reduced == reduced_.end()) {
    Eigen::MatrixXd dff(m, m);
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) dff(a, b) = dense_(free[a], free[b]);
    }
    reduced = reduced_.emplace(held, Eigen::LLT<Eigen::MatrixXd>(dff)).first;
  }
  Eigen::VectorXd gf(m);
  for (int a = 0; a < m; ++a) gf[a] = g[free[a]];
  const Eigen::VectorXd ff = -reduced->second.solve(gf);
  for (int a = 0; a < m; ++a) f[free[a]] = ff[a];
  return f;
}

std::vector<double> DampingMatrix::Apply(const std::vector<double>& v) const {
  if (!diagonal()) return AsVector(dense_ * AsEigen(v));
  std::vector<double> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = diag_[i] * v[i];
  return out;
}

double DampingMatrix::Norm(const std::vector<double>& v) const {
  if (!diagonal()) {
    const Eigen::VectorXd x = AsEigen(v);
    return std::sqrt(std::max(0.0, x.dot(dense_ * x)));
  }
  double sum = 0.0;
  for (size_t i = 0; i < v.size(); ++i) sum += diag_[i] * v[i] * v[i];
  return std::sqrt(sum);
}

// D^-1 J^T J is self-adjoint in the D inner product, so power iteration
// normalized in the D norm converges to its largest eigenvalue.  The
// diagonal case keeps LargestEigenvalue's arithmetic.
double DampingMatrix::LargestRate(const ceres::CRSMatrix& j) const {
  if (diagonal()) return LargestEigenvalue(j, diag_);
  Eigen::VectorXd x(j.num_cols);
  for (int c = 0; c < j.num_cols; ++c) x[c] = 1.0 + 0.5 * std::sin(c + 1.0);
  double lambda = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double norm = std::sqrt(x.dot(dense_ * x));
    if (!(norm > 0.0)) break;
    x /= norm;
    const Eigen::VectorXd z = factor_.solve(GaussNewtonProduct(j, x));
    const double next = std::sqrt(std::max(0.0, z.dot(dense_ * z)));
    const bool settled = std::abs(next - lambda) <= 1e-4 * next;
    lambda = next;
    x = z;
    if (settled) break;
  }
  return lambda;
}

std::vector<bool> HeldAtBounds(const ceres::Problem& problem,
                               const State& state,
                               const std::vector<double>& g) {
  std::vector<bool> held(state.tangent_size, false);
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    const double* x = state.blocks[b];
    if (problem.GetManifold(state.blocks[b]) != nullptr) continue;
    for (int i = 0; i < state.sizes[b]; ++i) {
      const double v = -g[state.offsets[b] + i];
      held[state.offsets[b] + i] =
          (v < 0.0 && x[i] <= problem.GetParameterLowerBound(x, i)) ||
          (v > 0.0 && x[i] >= problem.GetParameterUpperBound(x, i));
    }
  }
  return held;
}

}  // namespace pfdm
