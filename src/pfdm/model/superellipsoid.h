// The generalized superellipsoid primitive (paper eq. 5).
#ifndef PFDM_MODEL_SUPERELLIPSOID_H_
#define PFDM_MODEL_SUPERELLIPSOID_H_

#include "Eigen/Core"
#include "pfdm/model/parameter_function.h"
#include "pfdm/model/signed_power.h"

namespace pfdm {

// Trigonometry of one material point (u, v); T is double or a Jet when the
// angles themselves are differentiated (closest-point refinement).
template <typename T>
struct Angles {
  T cos_u, sin_u, cos_v, sin_v;
};

template <typename T>
Angles<T> MakeAngles(const T& u, const T& v) {
  using std::cos;
  using std::sin;
  return {cos(u), sin(u), cos(v), sin(v)};
}

// e = a0 (a1 Cu^e1 Cv^e2, a2 Cu^e1 Sv^e2, a3 Su^e1) with C^e = sgn(cos)|cos|^e
// and S^e = sgn(sin)|sin|^e.  f holds the parameter functions evaluated at u.
// unit_exponents skips the powers when eps1 = eps2 = 1 are held fixed.
template <typename T, typename A>
Eigen::Matrix<T, 3, 1> Superellipsoid(const T* f, const Angles<A>& angles,
                                      bool unit_exponents) {
  T cu, su, cv, sv;
  if (unit_exponents) {
    cu = T(angles.cos_u);
    su = T(angles.sin_u);
    cv = T(angles.cos_v);
    sv = T(angles.sin_v);
  } else {
    cu = SignedPower(T(angles.cos_u), f[kEps1]);
    su = SignedPower(T(angles.sin_u), f[kEps1]);
    cv = SignedPower(T(angles.cos_v), f[kEps2]);
    sv = SignedPower(T(angles.sin_v), f[kEps2]);
  }
  return Eigen::Matrix<T, 3, 1>(f[kA0] * f[kA1] * cu * cv,
                                f[kA0] * f[kA2] * cu * sv,
                                f[kA0] * f[kA3] * su);
}

// The ring's half extents across the axis in units of a0, (a1 Cu^e1,
// a2 Cu^e1): the amplitudes of e1 / a0 and e2 / a0 around the ring at u.
template <typename T, typename A>
Eigen::Matrix<T, 2, 1> RingHalfExtents(const T* f, const Angles<A>& angles,
                                       bool unit_exponents) {
  const T cu =
      unit_exponents ? T(angles.cos_u) : SignedPower(T(angles.cos_u), f[kEps1]);
  return Eigen::Matrix<T, 2, 1>(f[kA1] * cu, f[kA2] * cu);
}

}  // namespace pfdm

#endif  // PFDM_MODEL_SUPERELLIPSOID_H_
