// How far an explicit integrator still is from its rest point, measured as
// the direct solve measures it: by the Gauss-Newton step that is left.
#ifndef PFDM_SOLVERS_REST_ESTIMATE_H_
#define PFDM_SOLVERS_REST_ESTIMATE_H_

#include <optional>
#include <vector>

#include "Eigen/Dense"
#include "ceres/crs_matrix.h"

namespace pfdm {

// The start's Gauss-Newton matrix H = J^T J, factored once.  For the force
// g = J^T r at q, sqrt(g^T H^-1 g) = |J (q - q*)|: how far the residual
// vector still is from its value at the rest point q* (exactly so for
// affine residuals; for the frame fits, whose Jacobian changes little
// between the start and rest, to first order).  The dynamics never see it:
// it only decides when they have arrived (docs/dynamics.md).
class RestEstimate {
 public:
  // Dense: above this many columns the factorization would cost more than
  // the integration (2e8 flops at 1,000).
  static constexpr int kMaxColumns = 1000;

  // nullopt past kMaxColumns or if H is not positive definite to rounding.
  static std::optional<RestEstimate> FromJacobian(const ceres::CRSMatrix& j);

  // sqrt(g^T H^-1 g) for a tangent force g.
  double DistanceToRest(const std::vector<double>& gradient) const;

 private:
  // H scaled to unit diagonal, S H S, factored; S = diag(H)^-1/2.
  Eigen::VectorXd scale_;
  Eigen::LLT<Eigen::MatrixXd> factor_;
};

}  // namespace pfdm

#endif  // PFDM_SOLVERS_REST_ESTIMATE_H_
