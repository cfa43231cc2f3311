// The data term: one residual block per data point.
#ifndef PFDM_FIT_RESIDUALS_POINT_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_POINT_RESIDUAL_H_

#include "ceres/autodiff_cost_function.h"
#include "pfdm/model/model_point.h"

namespace pfdm {

// r = c + R(q) s(f(u_i); u_i, v_i, w_i) - d_i, where
// f(u_i) = (1 - w_i) knot_k + w_i knot_{k+1} for the free functions and the
// global block otherwise.  (u_i, v_i) is the data point's material point,
// held fixed during a solve, w_i its transmural coordinate (transmural.h);
// r is in mm.
class PointResidual {
 public:
  static constexpr int kNumResiduals = 3;

  PointResidual(const Eigen::Vector3d& data, double u, double v,
                double knot_weight, FunctionMask free_mask, bool unit_exponents,
                double w = 0.0)
      : data_(data),
        angles_(MakeAngles(u, v)),
        knot_weight_(knot_weight),
        free_mask_(free_mask),
        unit_exponents_(unit_exponents),
        w_(w) {}

  template <typename T>
  bool operator()(const T* center, const T* quaternion, const T* globals,
                  const T* knot0, const T* knot1, T* residual) const {
    const Eigen::Matrix<T, 3, 1> x =
        Position(center, quaternion, globals, knot0, knot1);
    for (int i = 0; i < 3; ++i) residual[i] = x[i] - data_[i];
    return true;
  }

  template <typename T>
  Eigen::Matrix<T, 3, 1> Position(const T* center, const T* quaternion,
                                  const T* globals, const T* knot0,
                                  const T* knot1) const {
    T f[kNumFunctions];
    InterpolateFunctions(free_mask_, globals, knot0, knot1, knot_weight_, f);
    return WorldFromModel(center, quaternion,
                          ReferenceShape(f, angles_, unit_exponents_, w_));
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& data, double u,
                                     double v, double knot_weight,
                                     FunctionMask free_mask,
                                     bool unit_exponents, double w = 0.0) {
    return new ceres::AutoDiffCostFunction<PointResidual, kNumResiduals, 3, 4,
                                           kNumFunctions, kNumFunctions,
                                           kNumFunctions>(new PointResidual(
        data, u, v, knot_weight, free_mask, unit_exponents, w));
  }

 private:
  Eigen::Vector3d data_;
  Angles<double> angles_;
  double knot_weight_;
  FunctionMask free_mask_;
  bool unit_exponents_;
  double w_;
};

// r = n_i . (c + R(q) s(f(u_i); u_i, v_i) - d_i): the point-to-plane
// residual for points with no tracked material point (contours, or any
// point while its closest material point is being found), n_i the unit
// surface normal at (u_i, v_i) before the solve.  Unlike the 3-vector it
// does not hold the surface back from sliding under the data, so the
// closest-point rounds converge in a few solves instead of creeping.
class SurfaceResidual {
 public:
  SurfaceResidual(const PointResidual& point, const Eigen::Vector3d& normal,
                  const Eigen::Vector3d& data)
      : point_(point), normal_(normal), data_(data) {}

  template <typename T>
  bool operator()(const T* center, const T* quaternion, const T* globals,
                  const T* knot0, const T* knot1, T* residual) const {
    const Eigen::Matrix<T, 3, 1> x =
        point_.Position(center, quaternion, globals, knot0, knot1);
    residual[0] = normal_[0] * (x[0] - data_[0]) +
                  normal_[1] * (x[1] - data_[1]) +
                  normal_[2] * (x[2] - data_[2]);
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& data, double u,
                                     double v, double knot_weight,
                                     FunctionMask free_mask,
                                     bool unit_exponents,
                                     const Eigen::Vector3d& normal,
                                     double w = 0.0) {
    return new ceres::AutoDiffCostFunction<
        SurfaceResidual, 1, 3, 4, kNumFunctions, kNumFunctions, kNumFunctions>(
        new SurfaceResidual(PointResidual(data, u, v, knot_weight, free_mask,
                                          unit_exponents, w),
                            normal, data));
  }

 private:
  PointResidual point_;
  Eigen::Vector3d normal_;
  Eigen::Vector3d data_;
};

// r = sqrt(w) (n . (c + R m) - top), m = (e1o, e2o, a0 a3 sin(u_max) + e3o)
// at u_max: the centre of the base rim (bending leaves a ring's mean height
// alone) at the highest data point along the world axis n, top being that
// point's n . x.  Contours say where the wall is, not which latitude a point
// has, so without it nothing stops an open model from reaching past the
// data; in world terms, since later frames move the pose.
class RimResidual {
 public:
  RimResidual(double sqrt_weight, double sin_u_max, const Eigen::Vector3d& axis,
              double top, FunctionMask free_mask)
      : sqrt_weight_(sqrt_weight),
        sin_u_max_(sin_u_max),
        axis_(axis),
        top_(top),
        free_mask_(free_mask) {}

  template <typename T>
  bool operator()(const T* center, const T* quaternion, const T* globals,
                  const T* last_knot, T* residual) const {
    auto value = [&](int f) {
      return (free_mask_ >> f) & 1u ? last_knot[f] : globals[f];
    };
    const Eigen::Matrix<T, 3, 1> rim_centre(
        value(kE1o), value(kE2o),
        value(kA0) * value(kA3) * sin_u_max_ + value(kE3o));
    const Eigen::Matrix<T, 3, 1> x =
        WorldFromModel(center, quaternion, rim_centre);
    residual[0] = sqrt_weight_ * (axis_.cast<T>().dot(x) - top_);
    return true;
  }

  static ceres::CostFunction* Create(double sqrt_weight, double sin_u_max,
                                     const Eigen::Vector3d& axis, double top,
                                     FunctionMask free_mask) {
    return new ceres::AutoDiffCostFunction<RimResidual, 1, 3, 4, kNumFunctions,
                                           kNumFunctions>(
        new RimResidual(sqrt_weight, sin_u_max, axis, top, free_mask));
  }

 private:
  double sqrt_weight_;
  double sin_u_max_;
  Eigen::Vector3d axis_;
  double top_;
  FunctionMask free_mask_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_POINT_RESIDUAL_H_
