#include "pfdm/solvers/rest_estimate.h"

#include <algorithm>
#include <cmath>

namespace pfdm {

// H from the CRS rows (sum over rows of the outer products of their
// entries), then scaled to unit diagonal so that the Cholesky factorization
// does not mix millimetres with radians.  A column that no residual sees
// makes H singular: no estimate.
std::optional<RestEstimate> RestEstimate::FromJacobian(
    const ceres::CRSMatrix& j) {
  const int n = j.num_cols;
  if (n == 0 || n > kMaxColumns) return std::nullopt;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < j.num_rows; ++r) {
    for (int a = j.rows[r]; a < j.rows[r + 1]; ++a) {
      for (int b = j.rows[r]; b < j.rows[r + 1]; ++b) {
        h(j.cols[a], j.cols[b]) += j.values[a] * j.values[b];
      }
    }
  }
  RestEstimate estimate;
  estimate.scale_.resize(n);
  for (int c = 0; c < n; ++c) {
    if (!(h(c, c) > 0.0)) return std::nullopt;
    estimate.scale_[c] = 1.0 / std::sqrt(h(c, c));
  }
  h = estimate.scale_.asDiagonal() * h * estimate.scale_.asDiagonal();
  estimate.factor_.compute(h);
  if (estimate.factor_.info() != Eigen::Success) return std::nullopt;
  return estimate;
}

double RestEstimate::DistanceToRest(const std::vector<double>& gradient) const {
  const Eigen::VectorXd g =
      scale_.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(
          gradient.data(), static_cast<Eigen::Index>(gradient.size())));
  return std::sqrt(std::max(0.0, g.dot(factor_.solve(g))));
}

}  // namespace pfdm
