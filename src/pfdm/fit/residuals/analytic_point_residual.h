// The data residuals of point_residual.h with hand-derived Jacobians,
// following the paper's chain xdot = [I  B  R J] qdot.
#ifndef PFDM_FIT_RESIDUALS_ANALYTIC_POINT_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_ANALYTIC_POINT_RESIDUAL_H_

#include <array>
#include <vector>

#include "ceres/cost_function.h"
#include "ceres/sized_cost_function.h"
#include "pfdm/model/model_point.h"

namespace pfdm {

// One data point tied to its material point.  With a normal it gives the
// point-to-plane residual n . (x - d), else the 3-vector x - d.
struct PointSample {
  Eigen::Vector3d data = Eigen::Vector3d::Zero();
  Angles<double> angles{1.0, 0.0, 1.0, 0.0};
  double knot_weight = 0.0;
  double w = 0.0;  // Transmural coordinate (transmural.h).
  bool has_normal = false;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();

  PointSample() = default;
  PointSample(const Eigen::Vector3d& data, double u, double v,
              double knot_weight);
  PointSample(const Eigen::Vector3d& data, double u, double v,
              double knot_weight, const Eigen::Vector3d& normal);
  int num_residuals() const { return has_normal ? 1 : 3; }
};

// Writes the sample's residual rows and, for each block asked for (non-null
// in jacobians), its Jacobian rows, row major.
void EvaluatePointSample(const PointSample& sample, FunctionMask free_mask,
                         bool unit_exponents, double const* const* parameters,
                         double* residuals, double** jacobians);

// Parameter blocks of every data residual: center (3), quaternion (4),
// globals, knot0, knot1 (kNumFunctions each).  With x = c + R(q) s(f):
//   dr/dc = I,
//   dr/dq = d(R(q) s)/dq for the ambient quaternion (w, v), as
//           UnitQuaternionRotatePoint evaluates R s = s + 2w v x s
//           + 2 v (v . s) - 2 s |v|^2,
//   dr/d(globals, knot0, knot1) = R ds/df times 1, (1 - w) or w on the
//           functions each block supplies (docs/jacobians.md),
// and n^T times all of that for a point-to-plane sample.
template <int kNumResiduals>
class AnalyticResidual
    : public ceres::SizedCostFunction<kNumResiduals, 3, 4, kNumFunctions,
                                      kNumFunctions, kNumFunctions> {
 public:
  AnalyticResidual(const PointSample& sample, FunctionMask free_mask,
                   bool unit_exponents)
      : sample_(sample),
        free_mask_(free_mask),
        unit_exponents_(unit_exponents) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    EvaluatePointSample(sample_, free_mask_, unit_exponents_, parameters,
                        residuals, jacobians);
    return true;
  }

 private:
  PointSample sample_;
  FunctionMask free_mask_;
  bool unit_exponents_;
};

using AnalyticPointResidual = AnalyticResidual<3>;    // Without a normal.
using AnalyticSurfaceResidual = AnalyticResidual<1>;  // With a normal.

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_ANALYTIC_POINT_RESIDUAL_H_
