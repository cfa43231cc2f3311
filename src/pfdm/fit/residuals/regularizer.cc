#include "pfdm/fit/residuals/regularizer.h"

#include <algorithm>

namespace pfdm {

FunctionValues RegularizerScales(const Model& model,
                                 const std::vector<int>& held) {
  const double a0 = model.state.globals[kA0];
  const double radius =
      a0 * 0.5 * (model.FunctionAt(kA1, 0.0) + model.FunctionAt(kA2, 0.0));
  FunctionValues scales{};
  scales[kA0] = 1.0;
  scales[kA1] = scales[kA2] = scales[kA3] = a0;
  scales[kEps1] = scales[kEps2] = radius;
  scales[kTau] = a0;
  scales[kB0] = scales[kB2] = scales[kE1o] = scales[kE2o] = scales[kE3o] = 1.0;
  scales[kB1] = scales[kB3] = radius;
  // A unit of h moves a wall surface by half a millimetre, one of shift by a
  // millimetre, one of squeeze the layers w = +-1/sqrt(3) by 0.38 mm; dtau
  // turns it by half as much as tau.
  scales[kH] = 0.5;
  scales[kWallShift] = 1.0;
  scales[kWallSqueeze] = 0.385;
  scales[kDtau] = 0.5 * a0;
  for (int f : held) scales[f] = 0.0;
  return scales;
}

bool SmoothnessResidual::Evaluate(double const* const* parameters,
                                  double* residuals, double** jacobians) const {
  const double* previous = parameters[0];
  const double* knot = parameters[1];
  const double* next = parameters[2];
  for (int f = 0; f < kNumFunctions; ++f) {
    residuals[f] =
        sqrt_weight_ * scales_[f] * (previous[f] - 2.0 * knot[f] + next[f]);
  }
  if (jacobians == nullptr) return true;
  const double along[3] = {1.0, -2.0, 1.0};
  for (int b = 0; b < 3; ++b) {
    if (jacobians[b] == nullptr) continue;
    std::fill(jacobians[b], jacobians[b] + kNumFunctions * kNumFunctions, 0.0);
    for (int f = 0; f < kNumFunctions; ++f) {
      jacobians[b][f * kNumFunctions + f] =
          sqrt_weight_ * scales_[f] * along[b];
    }
  }
  return true;
}

bool PriorResidual::Evaluate(double const* const* parameters, double* residuals,
                             double** jacobians) const {
  const double* values = parameters[0];
  for (int f = 0; f < kNumFunctions; ++f) {
    residuals[f] = sqrt_weight_ * scales_[f] * (values[f] - prior_[f]);
  }
  if (jacobians == nullptr || jacobians[0] == nullptr) return true;
  std::fill(jacobians[0], jacobians[0] + kNumFunctions * kNumFunctions, 0.0);
  for (int f = 0; f < kNumFunctions; ++f) {
    jacobians[0][f * kNumFunctions + f] = sqrt_weight_ * scales_[f];
  }
  return true;
}

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
