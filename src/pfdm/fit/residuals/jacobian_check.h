// Checks the data residuals' Jacobians against central differences
// (ceres::GradientChecker) over model states that include the singular ones.
#ifndef PFDM_FIT_RESIDUALS_JACOBIAN_CHECK_H_
#define PFDM_FIT_RESIDUALS_JACOBIAN_CHECK_H_

#include <array>
#include <string>
#include <vector>

#include "pfdm/fit/residuals/data_cost.h"

namespace pfdm {

struct JacobianCheck {
  std::string state;     // e.g. "apex pole", "eps = 1", "zero bending".
  std::string residual;  // "point" or "surface".
  JacobianKind jacobian = JacobianKind::kAnalytic;
  // Per parameter block (center, quaternion, globals, knot0, knot1): the
  // largest |J - J_numeric| over the block, relative to the block's largest
  // numeric entry (entries that should be zero make entry-wise relative
  // errors meaningless).  In the quaternion's tangent space.
  std::array<double, 5> block_error{};
  double worst = 0.0;
  bool finite = true;
};

// Every state x {point, surface} x {analytic, autodiff}.
std::vector<JacobianCheck> CheckJacobians();

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_JACOBIAN_CHECK_H_
