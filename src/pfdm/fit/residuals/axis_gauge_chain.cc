#include "pfdm/fit/residuals/axis_gauge_chain.h"

#include <algorithm>
#include <cmath>

#include "ceres/normal_prior.h"

namespace pfdm {

AxisGaugeChain::AxisGaugeChain(const std::vector<const double*>& knots,
                               double sqrt_weight)
    : sqrt_weight_(sqrt_weight), sums_(knots.size()) {
  const int num_knots = static_cast<int>(knots.size());
  std::array<double, 4> partial{};
  for (int k = 0; k < num_knots; ++k) {
    double term[4];
    AxisGaugeCoefficients(k, num_knots, sqrt_weight).Term(knots[k], term);
    for (int i = 0; i < 4; ++i) partial[i] += term[i];
    sums_[k] = partial;
  }
  // Less the links' equal shares of r, the whole sum.
  const std::array<double, 4> r = partial;
  for (int k = 0; k < num_knots; ++k) {
    for (int i = 0; i < 4; ++i) sums_[k][i] -= (k + 1) * r[i] / (2 * num_knots);
  }
}

ceres::CostFunction* AxisGaugeChain::Link(int k) const {
  return new AxisGaugeLinkResidual(k, num_knots(), sqrt_weight_);
}

ceres::CostFunction* AxisGaugeChain::End() const {
  return new ceres::NormalPrior(std::sqrt(2.0) * ceres::Matrix::Identity(4, 4),
                                ceres::Vector::Zero(4));
}

std::vector<double*> AxisGaugeChain::LinkSums(int k) {
  if (k == 0) return {sum(0)};
  return {sum(k - 1), sum(k)};
}

AxisGaugeLinkResidual::AxisGaugeLinkResidual(int k, int num_knots,
                                             double sqrt_weight)
    : first_(k == 0),
      scale_(std::sqrt(2.0 * num_knots)),
      coefficients_(k, num_knots, sqrt_weight) {
  set_num_residuals(4);
  if (!first_) mutable_parameter_block_sizes()->push_back(4);
  mutable_parameter_block_sizes()->push_back(4);
  mutable_parameter_block_sizes()->push_back(kNumFunctions);
}

bool AxisGaugeLinkResidual::Evaluate(double const* const* parameters,
                                     double* residuals,
                                     double** jacobians) const {
  const int at = first_ ? 0 : 1;  // s_k's block; s_{k-1}'s is 0.
  const double* sum = parameters[at];
  double term[4];
  coefficients_.Term(parameters[at + 1], term);
  for (int i = 0; i < 4; ++i) {
    const double previous = first_ ? 0.0 : parameters[0][i];
    residuals[i] = scale_ * (sum[i] - previous - term[i]);
  }
  if (jacobians == nullptr) return true;
  for (int b = 0; b < at + 1; ++b) {
    if (jacobians[b] == nullptr) continue;
    const double sign = b == at ? scale_ : -scale_;
    std::fill(jacobians[b], jacobians[b] + 16, 0.0);
    for (int i = 0; i < 4; ++i) jacobians[b][5 * i] = sign;
  }
  if (jacobians[at + 1] != nullptr) {
    coefficients_.Jacobian(-scale_, jacobians[at + 1]);
  }
  return true;
}

}  // namespace pfdm
