// The data residuals of point_residual.h with hand-derived Jacobians,
// following the paper's chain xdot = [I  B  R J] qdot.
#ifndef PFDM_ANALYTIC_POINT_RESIDUAL_H_
#define PFDM_ANALYTIC_POINT_RESIDUAL_H_

#include "ceres/sized_cost_function.h"
#include "pfdm/model_point.h"

namespace pfdm {

// r = c + R(q) s(f) - d (or n . that, with a normal).  Jacobians:
//   dr/dc = I,
//   dr/dq = d(R(q) s)/dq for the ambient quaternion (w, v), as
//           UnitQuaternionRotatePoint evaluates R s = s + 2w v x s
//           + 2 v (v . s) - 2 s |v|^2,
//   dr/d(knot0, knot1, globals) = R ds/df times (1 - w), w or 1 on the
//           functions each block supplies (see docs/jacobians.md).
class AnalyticPointResidual
    : public ceres::SizedCostFunction<3, 3, 4, kNumFunctions, kNumFunctions,
                                      kNumFunctions> {
 public:
  AnalyticPointResidual(const Eigen::Vector3d& data, double u, double v,
                        double knot_weight, FunctionMask free_mask,
                        bool unit_exponents);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector3d data_;
  Angles<double> angles_;
  double knot_weight_;
  FunctionMask free_mask_;
  bool unit_exponents_;
};

// n . (c + R(q) s(f) - d): the point-to-plane residual.
class AnalyticSurfaceResidual
    : public ceres::SizedCostFunction<1, 3, 4, kNumFunctions, kNumFunctions,
                                      kNumFunctions> {
 public:
  AnalyticSurfaceResidual(const Eigen::Vector3d& data, double u, double v,
                          double knot_weight, FunctionMask free_mask,
                          bool unit_exponents, const Eigen::Vector3d& normal);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  AnalyticPointResidual point_;
  Eigen::Vector3d normal_;
};

}  // namespace pfdm

#endif  // PFDM_ANALYTIC_POINT_RESIDUAL_H_
