// The gauge that holds frame 0's apex along the long axis where no data
// reach it.
#ifndef PFDM_FIT_RESIDUALS_APEX_GAUGE_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_APEX_GAUGE_RESIDUAL_H_

#include "Eigen/Core"
#include "ceres/autodiff_cost_function.h"
#include "ceres/rotation.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// r = sqrt(w) (z0 . (c + R(q) (0, 0, a0 s)) - h0): the height of the apex
// pole's axis point along the start's long axis z0 against the start's h0,
// s = a3(u_min) sin(u_min) (a3 is held on frame 0, and the apex is neither
// bent nor offset along the axis there).  Frame 0's data fix the model from
// their lowest point to the rim; below them a shorter model (a0 down, the
// centre up, a1 and a2 up to keep the radii) fits them nearly as well, so
// on a segment without an apex the apex slid a little each round and the
// rounds ran out unsettled.  Held at the start's, the apex stays where the
// start put it unless the data say otherwise.
class ApexGaugeResidual {
 public:
  ApexGaugeResidual(double sqrt_weight, double apex_extent,
                    const Eigen::Vector3d& axis, double height)
      : sqrt_weight_(sqrt_weight),
        apex_extent_(apex_extent),
        axis_(axis),
        height_(height) {}

  template <typename T>
  bool operator()(const T* center, const T* q, const T* globals,
                  T* residual) const {
    const T apex[3] = {T(0.0), T(0.0), globals[kA0] * apex_extent_};
    T rotated[3];
    ceres::UnitQuaternionRotatePoint(q, apex, rotated);
    T height = T(-height_);
    for (int i = 0; i < 3; ++i) height += axis_[i] * (center[i] + rotated[i]);
    residual[0] = sqrt_weight_ * height;
    return true;
  }

  static ceres::CostFunction* Create(double sqrt_weight, double apex_extent,
                                     const Eigen::Vector3d& axis,
                                     double height) {
    return new ceres::AutoDiffCostFunction<ApexGaugeResidual, 1, 3, 4,
                                           kNumFunctions>(
        new ApexGaugeResidual(sqrt_weight, apex_extent, axis, height));
  }

 private:
  double sqrt_weight_;
  double apex_extent_;
  Eigen::Vector3d axis_;
  double height_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_APEX_GAUGE_RESIDUAL_H_
