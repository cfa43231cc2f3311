// The stiffness term K q of the paper as least-squares residuals: smoothness
// of each free function across knots and a pull toward a prior state.
#ifndef PFDM_FIT_RESIDUALS_REGULARIZER_H_
#define PFDM_FIT_RESIDUALS_REGULARIZER_H_

#include <vector>

#include "ceres/autodiff_cost_function.h"
#include "ceres/cost_function.h"
#include "ceres/sized_cost_function.h"
#include "pfdm/model/model.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// Millimetres of model-point motion per unit of each function, for the
// regularizers: 0 for the `held` functions.  Everything scales with the
// data, so scaled data get scaled lengths.  tau is weighted as if at
// radius a0, about four times the LV's: near the apex the rings are too
// small for the data to pin the twist, and twist varies slowly along the
// axis, so its smoothness carries more.
FunctionValues RegularizerScales(const Model& model,
                                 const std::vector<int>& held);

// r_f = sqrt(w) s_f (k_{j-1,f} - 2 k_{j,f} + k_{j+1,f}) for the functions
// with s_f != 0: the second difference, so that a linear trend in u costs
// nothing.  s_f converts function f to mm.
//
// The residuals are linear, so the Jacobians are the constant diagonals
// sqrt(w) s_f (1, -2, 1): written out, not taken by autodiff, whose
// 54-derivative Jets at every iteration of every knot were 2-3 % of a
// contour job.  The same values to the bit (autodiff's are these products).
class SmoothnessResidual
    : public ceres::SizedCostFunction<kNumFunctions, kNumFunctions,
                                      kNumFunctions, kNumFunctions> {
 public:
  SmoothnessResidual(double sqrt_weight, const FunctionValues& scales)
      : sqrt_weight_(sqrt_weight), scales_(scales) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  static ceres::CostFunction* Create(double sqrt_weight,
                                     const FunctionValues& scales) {
    return new SmoothnessResidual(sqrt_weight, scales);
  }

 private:
  double sqrt_weight_;
  FunctionValues scales_;
};

// r_f = sqrt(w) s_f (x_f - prior_f): holds directions the data leave free
// (b1 while b0 = 0, a1 at the apex) near the previous frame.  Its Jacobian
// is the constant diagonal sqrt(w) s_f (as SmoothnessResidual's).
class PriorResidual
    : public ceres::SizedCostFunction<kNumFunctions, kNumFunctions> {
 public:
  PriorResidual(double sqrt_weight, const FunctionValues& scales,
                const FunctionValues& prior)
      : sqrt_weight_(sqrt_weight), scales_(scales), prior_(prior) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  static ceres::CostFunction* Create(double sqrt_weight,
                                     const FunctionValues& scales,
                                     const FunctionValues& prior) {
    return new PriorResidual(sqrt_weight, scales, prior);
  }

 private:
  double sqrt_weight_;
  FunctionValues scales_;
  FunctionValues prior_;
};

// Knot k's term of AxisGaugeResidual's r (below), (m e1o_k, m e2o_k, t e1o_k,
// t e2o_k): its mean coefficient m = sqrt(w) / K and trend coefficient
// t = sqrt(w) c_k / K.
struct AxisGaugeCoefficients {
  AxisGaugeCoefficients(int k, int num_knots, double sqrt_weight)
      : mean(sqrt_weight / num_knots),
        trend(sqrt_weight * (k - 0.5 * (num_knots - 1)) / num_knots) {}
  // The term for knot values `knot` (a whole block).
  void Term(const double* knot, double* term) const {
    term[0] = mean * knot[kE1o];
    term[1] = mean * knot[kE2o];
    term[2] = trend * knot[kE1o];
    term[3] = trend * knot[kE2o];
  }
  // d term / d knot, 4 x kNumFunctions row major, scaled by `scale`.
  void Jacobian(double scale, double* jacobian) const;

  double mean, trend;
};

// r = sqrt(w) (sum_k e1o_k, sum_k e2o_k, sum_k c_k e1o_k, sum_k c_k e2o_k)
// / K with c_k = k - (K - 1) / 2, over the K knot blocks: zero when the
// ring centres scatter about the model axis with no mean and no linear
// trend, i.e. the axis is their least-squares line.  A strong weight makes
// it the frame-0 gauge that lets the pose alone carry the axis.
// AxisGaugeChain (axis_gauge_chain.h) is the same penalty with a sparse
// J^T J.
class AxisGaugeResidual : public ceres::CostFunction {
 public:
  AxisGaugeResidual(int num_knots, double sqrt_weight);
  bool Evaluate(double const* const* knots, double* residuals,
                double** jacobians) const override;

 private:
  std::vector<AxisGaugeCoefficients> coefficients_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_REGULARIZER_H_
