// The gauge that keeps rotation about the long axis out of the pose on
// frames after the first.
#ifndef PFDM_FIT_RESIDUALS_SPIN_GAUGE_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_SPIN_GAUGE_RESIDUAL_H_

#include <array>

#include "ceres/autodiff_cost_function.h"

namespace pfdm {

// r = sqrt(w) 2 rho z(q0* q): the z component of the rotation from frame
// 0's pose q0 to this frame's q, in frame 0's model frame, times a length
// rho (mm per radian of spin).  Write q0* q as a swing (about an axis normal
// to z) times a twist about z: its z component is cos(swing/2) sin(twist/2),
// zero exactly when the twist is.  A spin of the pose about the model's
// long axis and a constant tau move every point alike (the offsets' gauge
// is invariant under the spin), so without this the data cannot tell them
// apart; with it, rotation about the axis stays in tau, relative to frame 0,
// while the pose carries translation and tilt.
class SpinGaugeResidual {
 public:
  SpinGaugeResidual(double sqrt_weight, double length_mm,
                    const std::array<double, 4>& reference)
      : scale_(2.0 * sqrt_weight * length_mm), reference_(reference) {}

  template <typename T>
  bool operator()(const T* q, T* residual) const {
    const double w0 = reference_[0], x0 = reference_[1], y0 = reference_[2],
                 z0 = reference_[3];
    residual[0] = scale_ * (w0 * q[3] - x0 * q[2] + y0 * q[1] - z0 * q[0]);
    return true;
  }

  static ceres::CostFunction* Create(double sqrt_weight, double length_mm,
                                     const std::array<double, 4>& reference) {
    return new ceres::AutoDiffCostFunction<SpinGaugeResidual, 1, 4>(
        new SpinGaugeResidual(sqrt_weight, length_mm, reference));
  }

 private:
  double scale_;
  std::array<double, 4> reference_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_SPIN_GAUGE_RESIDUAL_H_
