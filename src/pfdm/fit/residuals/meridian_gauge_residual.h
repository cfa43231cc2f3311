// The gauge of frames without tracked points: how u runs along the meridian.
#ifndef PFDM_FIT_RESIDUALS_MERIDIAN_GAUGE_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_MERIDIAN_GAUGE_RESIDUAL_H_

#include "ceres/autodiff_cost_function.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// r = sqrt(w) a0 (a3_{k+1} - a3_k) over two neighbouring knots.  Contours
// fix a surface's radius at each height, not which latitude u sits there:
// a3's profile and a1, a2 can trade along the meridian without moving the
// surface, so a frame without tracked points would drift between them.
// With a3 equal at every knot, as on frame 0, u runs along the axis as it
// does there, a1 and a2 read the radius at the same fraction of the length,
// and a3 the length itself.
class MeridianGaugeResidual {
 public:
  MeridianGaugeResidual(double sqrt_weight, double a0)
      : scale_(sqrt_weight * a0) {}

  template <typename T>
  bool operator()(const T* knot, const T* next, T* residual) const {
    residual[0] = scale_ * (next[kA3] - knot[kA3]);
    return true;
  }

  static ceres::CostFunction* Create(double sqrt_weight, double a0) {
    return new ceres::AutoDiffCostFunction<MeridianGaugeResidual, 1,
                                           kNumFunctions, kNumFunctions>(
        new MeridianGaugeResidual(sqrt_weight, a0));
  }

 private:
  double scale_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_MERIDIAN_GAUGE_RESIDUAL_H_
