#include "pfdm/fit/regularizer.h"

#include <algorithm>

namespace pfdm {

AxisGaugeResidual::AxisGaugeResidual(int num_knots, double sqrt_weight) {
  set_num_residuals(4);
  for (int k = 0; k < num_knots; ++k) {
    mutable_parameter_block_sizes()->push_back(kNumFunctions);
    mean_coefficients_.push_back(sqrt_weight / num_knots);
    trend_coefficients_.push_back(sqrt_weight * (k - 0.5 * (num_knots - 1)) /
                                  num_knots);
  }
}

bool AxisGaugeResidual::Evaluate(double const* const* knots, double* residuals,
                                 double** jacobians) const {
  const int num_knots = static_cast<int>(mean_coefficients_.size());
  std::fill(residuals, residuals + 4, 0.0);
  for (int k = 0; k < num_knots; ++k) {
    residuals[0] += mean_coefficients_[k] * knots[k][kE1o];
    residuals[1] += mean_coefficients_[k] * knots[k][kE2o];
    residuals[2] += trend_coefficients_[k] * knots[k][kE1o];
    residuals[3] += trend_coefficients_[k] * knots[k][kE2o];
    if (jacobians == nullptr || jacobians[k] == nullptr) continue;
    double* jacobian = jacobians[k];  // 4 x kNumFunctions, row major.
    std::fill(jacobian, jacobian + 4 * kNumFunctions, 0.0);
    jacobian[0 * kNumFunctions + kE1o] = mean_coefficients_[k];
    jacobian[1 * kNumFunctions + kE2o] = mean_coefficients_[k];
    jacobian[2 * kNumFunctions + kE1o] = trend_coefficients_[k];
    jacobian[3 * kNumFunctions + kE2o] = trend_coefficients_[k];
  }
  return true;
}

}  // namespace pfdm
