// The axis gauge of AxisGaugeResidual (regularizer.h) with the sparsity of
// a chain.  AxisGaugeResidual's four rows sum over every knot, and Ceres
// couples whole parameter blocks: every knot's block of J^T J met every
// other's, the normal equations of a frame (176 unknowns) were dense, and
// Eigen's simplicial factorization of them took about 1 ms an LM iteration
// at any number of points, most of the linear solve.
//
// The chain carries partial sums s_0 .. s_{K-1} (4 each) of the gauge's
// per-knot terms b_k (AxisGaugeCoefficients) instead:
//   link k:  sqrt(2K) (s_k - s_{k-1} - b_k(e_k)),  s_{-1} = 0,
//   end:     sqrt(2) s_{K-1},
// each link over its own knot only.  Minimized over the sums (springs in
// series: every link takes the same share d of r = sum_k b_k, and
// 2K d = 2 (r - K d) gives d = r / 2K), the chain costs
//   K (2K / 2) |r / 2K|^2 + (2 / 2) |r / 2|^2 = 1/2 |r|^2,
// AxisGaugeResidual's cost exactly: the same penalty on the knots, so the
// same minimum, reached with a banded J^T J.
//
// Only tracked frames' direct solves use it.  The sums must move far when
// the offsets shift together, and LM damps them as it damps everything:
// a solve that needs damping (frame 0's rounds, which start far off) then
// creeps, as the solid's frame 0 did (1,058 iterations, not converged,
// against 236).  Tracked frames start at the previous frame's fit and take
// undamped steps (SolveDirect).  The damped and integrator solvers keep
// AxisGaugeResidual too: there the sums would be state with a path of
// their own.
#ifndef PFDM_FIT_RESIDUALS_AXIS_GAUGE_CHAIN_H_
#define PFDM_FIT_RESIDUALS_AXIS_GAUGE_CHAIN_H_

#include <array>
#include <vector>

#include "ceres/cost_function.h"
#include "pfdm/fit/residuals/regularizer.h"

namespace pfdm {

class AxisGaugeChain {
 public:
  // knots: the K knots' whole values.  The sums start at their minimum for
  // these, where the chain's cost is AxisGaugeResidual's.
  AxisGaugeChain(const std::vector<const double*>& knots, double sqrt_weight);

  int num_knots() const { return static_cast<int>(sums_.size()); }
  // The parameter block of s_k (4 values).
  double* sum(int k) { return sums_[k].data(); }

  // Link k over (s_{k-1} unless k = 0, s_k, knot k's whole block); the
  // caller owns it.
  ceres::CostFunction* Link(int k) const;
  // The end over s_{K-1}; the caller owns it.
  ceres::CostFunction* End() const;
  // Link k's sum blocks, in Link(k)'s order.
  std::vector<double*> LinkSums(int k);

 private:
  double sqrt_weight_;
  std::vector<std::array<double, 4>> sums_;
};

// Link k of a chain of K: r = sqrt(2K) (s_k - s_{k-1} - b_k(e_k)).
class AxisGaugeLinkResidual : public ceres::CostFunction {
 public:
  AxisGaugeLinkResidual(int k, int num_knots, double sqrt_weight);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  bool first_;
  double scale_;
  AxisGaugeCoefficients coefficients_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_AXIS_GAUGE_CHAIN_H_
