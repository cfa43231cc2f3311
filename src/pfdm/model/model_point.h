// A model point: parameter functions interpolated at u, the reference shape
// s = T_o(T_twist(T_b(e))) and the pose x = c + R s.
#ifndef PFDM_MODEL_MODEL_POINT_H_
#define PFDM_MODEL_MODEL_POINT_H_

#include <cstdint>

#include "Eigen/Core"
#include "ceres/rotation.h"
#include "pfdm/model/global_deformations.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/model/superellipsoid.h"
#include "pfdm/model/transmural.h"

namespace pfdm {

// Bit f set: function f is piecewise linear over the knots; clear: it takes
// its one value from the global block (fitted constant, or held).
using FunctionMask = std::uint32_t;

// f = (1 - w) knot0 + w knot1 for the functions in free_mask, globals
// otherwise.  Only the two knots around u enter, which keeps the Jacobian
// sparse.
template <typename T, typename W>
void InterpolateFunctions(FunctionMask free_mask, const T* globals,
                          const T* knot0, const T* knot1, const W& weight,
                          T* f) {
  for (int i = 0; i < kNumFunctions; ++i) {
    f[i] = (free_mask >> i) & 1u ? (1.0 - weight) * knot0[i] + weight * knot1[i]
                                 : globals[i];
  }
}

// d f / du of InterpolateFunctions within a knot span `width` long in u:
// (knot1 - knot0) / width for the free functions, 0 for the others.
inline void InterpolateFunctionSlopes(FunctionMask free_mask,
                                      const double* knot0, const double* knot1,
                                      double width, double* slopes) {
  for (int i = 0; i < kNumFunctions; ++i) {
    slopes[i] = (free_mask >> i) & 1u ? (knot1[i] - knot0[i]) / width : 0.0;
  }
}

// The point of surface w (transmural.h; 0: the mid-wall).  The bend's ring
// mean is the mid-wall ring's on every surface.
template <typename T, typename A>
Eigen::Matrix<T, 3, 1> ReferenceShape(const T* f, const Angles<A>& angles,
                                      bool unit_exponents, double w = 0.0) {
  Eigen::Matrix<T, 3, 1> e = Superellipsoid(f, angles, unit_exponents);
  if (w != 0.0) e += WallOffset(f, angles, w);
  return Offset(f,
                Twist(TwistAt(f, w),
                      Bend(f, e, RingHalfExtents(f, angles, unit_exponents))));
}

// x = c + R(q) p with q = (w, x, y, z) a unit quaternion.
template <typename T>
Eigen::Matrix<T, 3, 1> WorldFromModel(const T* center, const T* quaternion,
                                      const Eigen::Matrix<T, 3, 1>& p) {
  Eigen::Matrix<T, 3, 1> x;
  ceres::UnitQuaternionRotatePoint(quaternion, p.data(), x.data());
  return x + Eigen::Map<const Eigen::Matrix<T, 3, 1>>(center);
}

}  // namespace pfdm

#endif  // PFDM_MODEL_MODEL_POINT_H_
