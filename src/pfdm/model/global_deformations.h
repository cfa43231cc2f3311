// Bending (eq. 7), twisting (eq. 8) and axis offsets (eq. 6), each a map of
// model-frame points driven by parameter functions evaluated at the point's u.
#ifndef PFDM_MODEL_GLOBAL_DEFORMATIONS_H_
#define PFDM_MODEL_GLOBAL_DEFORMATIONS_H_

#include <cmath>

#include "Eigen/Core"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// T_b(e) = (e1, e2, e3 + b0 g(e1 / e1max, b1) + b2 g(e2 / e1max, b3)),
// g(x, b) = cos(pi/2 (x - b)) - cos(pi/2 b).
// Our reading of eq. 7: the bend moves points along the long axis as a
// function of where they sit across the ring, e1max being the primitive's
// largest extent, which with 0 <= a1..a3 <= 1 is a0.  b = +-1 tilts the ring
// (g = +-sin(pi/2 x)), b = 0 cups it.  g vanishes at the ring centre: a bend
// that moved whole rings would duplicate a3 (along the axis) or the offsets
// e1o, e2o (across it) exactly, and the fit could not tell them apart.
template <typename T>
T BendProfile(const T& x, const T& b) {
  using std::cos;
  constexpr double kHalfPi = 1.57079632679489661923;
  return cos(kHalfPi * (x - b)) - cos(kHalfPi * b);
}

template <typename T>
Eigen::Matrix<T, 3, 1> Bend(const T* f, const Eigen::Matrix<T, 3, 1>& e) {
  const T e1max = f[kA0];
  return Eigen::Matrix<T, 3, 1>(
      e[0], e[1],
      e[2] + f[kB0] * BendProfile(T(e[0] / e1max), f[kB1]) +
          f[kB2] * BendProfile(T(e[1] / e1max), f[kB3]));
}

// T_twist(e) = Rz(tau) e: a right-handed rotation by tau about axis 3.
template <typename T>
Eigen::Matrix<T, 3, 1> Twist(const T* f, const Eigen::Matrix<T, 3, 1>& e) {
  using std::cos;
  using std::sin;
  const T c = cos(f[kTau]);
  const T s = sin(f[kTau]);
  return Eigen::Matrix<T, 3, 1>(c * e[0] - s * e[1], s * e[0] + c * e[1], e[2]);
}

// T_o(e) = e + (e1o, e2o, e3o).
template <typename T>
Eigen::Matrix<T, 3, 1> Offset(const T* f, const Eigen::Matrix<T, 3, 1>& e) {
  return Eigen::Matrix<T, 3, 1>(e[0] + f[kE1o], e[1] + f[kE2o], e[2] + f[kE3o]);
}

}  // namespace pfdm

#endif  // PFDM_MODEL_GLOBAL_DEFORMATIONS_H_
