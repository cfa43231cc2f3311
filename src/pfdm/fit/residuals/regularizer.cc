#include "pfdm/fit/residuals/regularizer.h"

#include <algorithm>

namespace pfdm {

AxisGaugeResidual::AxisGaugeResidual(int num_knots, double sqrt_weight) {
  set_num_residuals(4);
  for (int k = 0; k < num_knots; ++k) {
    mutable_parameter_block_sizes()->push_back(kNumFunctions);
    coefficients_.emplace_back(k, num_knots, sqrt_weight);
  }
}

bool AxisGaugeResidual::Evaluate(double const* const* knots, double* residuals,
                                 double** jacobians) const {
  const int num_knots = static_cast<int>(coefficients_.size());
  std::fill(residuals, residuals + 4, 0.0);
  for (int k = 0; k < num_knots; ++k) {
    double term[4];
    coefficients_[k].Term(knots[k], term);
    for (int i = 0; i < 4; ++i) residuals[i] += term[i];
    if (jacobians != nullptr && jacobians[k] != nullptr) {
      coefficients_[k].Jacobian(1.0, jacobians[k]);
    }
  }
  return true;
}

void AxisGaugeCoefficients::Jacobian(double scale, double* jacobian) const {
  std::fill(jacobian, jacobian + 4 * kNumFunctions, 0.0);
  jacobian[0 * kNumFunctions + kE1o] = scale * mean;
  jacobian[1 * kNumFunctions + kE2o] = scale * mean;
  jacobian[2 * kNumFunctions + kE1o] = scale * trend;
  jacobian[3 * kNumFunctions + kE2o] = scale * trend;
}

}  // namespace pfdm
