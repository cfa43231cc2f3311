// Bending (eq. 7), twisting (eq. 8) and axis offsets (eq. 6), each a map of
// model-frame points driven by parameter functions evaluated at the point's u.
#ifndef PFDM_MODEL_GLOBAL_DEFORMATIONS_H_
#define PFDM_MODEL_GLOBAL_DEFORMATIONS_H_

#include <cmath>

#include "Eigen/Core"
#include "ceres/jet.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// T_b(e) = (e1, e2, e3 + b0 g(e1 / e1max, b1, r1) + b2 g(e2 / e1max, b3, r2)),
// g(x, b, r) = cos(pi/2 (x - b)) - J0(pi/2 r) cos(pi/2 b).
// Our reading of eq. 7: the bend moves points along the long axis as a
// function of where they sit across the ring, e1max being the primitive's
// largest extent, which with 0 <= a1..a3 <= 1 is a0.  b = +-1 tilts the ring
// (g = +-sin(pi/2 x)), b = 0 cups it.  r is the ring's half extent in the
// same units (r1 = a1 Cu^e1, r2 = a2 Cu^e1: RingHalfExtents), and the
// subtracted term is the mean of cos(pi/2 (x - b)) over the ring, since for
// x = r cos v the mean over v of cos(pi/2 (r cos v - b)) is
// J0(pi/2 r) cos(pi/2 b).  So a bend never moves a ring's mean height: that
// stays with a3 and the pose, and the cup becomes a pure change of the
// ring's shape (a bend that moved whole rings would duplicate a3 or a rigid
// shift along the axis, and the fit could not tell them apart).  With
// eps2 != 1 the subtracted term is the elliptic ring's mean, not the
// superelliptic one's (docs/jacobians.md).
template <typename T>
T BendProfile(const T& x, const T& b, const T& half_extent) {
  using ceres::BesselJ0;
  using std::cos;
  constexpr double kHalfPi = 1.57079632679489661923;
  return cos(kHalfPi * (x - b)) -
         BesselJ0(T(kHalfPi * half_extent)) * cos(kHalfPi * b);
}

// ring: the ring's half extents (RingHalfExtents).
template <typename T>
Eigen::Matrix<T, 3, 1> Bend(const T* f, const Eigen::Matrix<T, 3, 1>& e,
                            const Eigen::Matrix<T, 2, 1>& ring) {
  const T e1max = f[kA0];
  return Eigen::Matrix<T, 3, 1>(
      e[0], e[1],
      e[2] + f[kB0] * BendProfile(T(e[0] / e1max), f[kB1], ring[0]) +
          f[kB2] * BendProfile(T(e[1] / e1max), f[kB3], ring[1]));
}

// T_twist(e) = Rz(tau) e: a right-handed rotation by tau about axis 3 (the
// function tau, or the twist of a surface off the mid-wall: TwistAt).
template <typename T>
Eigen::Matrix<T, 3, 1> Twist(const T& tau, const Eigen::Matrix<T, 3, 1>& e) {
  using std::cos;
  using std::sin;
  const T c = cos(tau);
  const T s = sin(tau);
  return Eigen::Matrix<T, 3, 1>(c * e[0] - s * e[1], s * e[0] + c * e[1], e[2]);
}

// T_o(e) = e + (e1o, e2o, e3o).
template <typename T>
Eigen::Matrix<T, 3, 1> Offset(const T* f, const Eigen::Matrix<T, 3, 1>& e) {
  return Eigen::Matrix<T, 3, 1>(e[0] + f[kE1o], e[1] + f[kE2o], e[2] + f[kE3o]);
}

}  // namespace pfdm

#endif  // PFDM_MODEL_GLOBAL_DEFORMATIONS_H_
