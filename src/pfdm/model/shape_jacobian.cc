#include "pfdm/model/shape_jacobian.h"

#include <algorithm>
#include <cmath>

#include "pfdm/model/transmural.h"
#include "pfdm/util/bessel.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

enum ShapeAngle { kPhase1, kBend1, kPhase2, kBend2, kTwist };

// SignedPower and its derivative in the exponent:
// d/de [x (x^2 + d^2)^((e-1)/2)] = SignedPower(x, e) ln(x^2 + d^2) / 2.
Power PowerOf(double x, double e, bool unit_exponents) {
  if (unit_exponents) return {x, 0.0};
  const double base = x * x + kSignedPowerDelta * kSignedPowerDelta;
  const double value = SignedPower(x, e);
  return {value, 0.5 * value * std::log(base)};
}

}  // namespace

ShapePrelude PrepareShape(const double* f, const Angles<double>& angles,
                          bool unit_exponents, double w,
                          const ShapePrelude* same_ring) {
  ShapePrelude prelude;
  prelude.cu = PowerOf(angles.cos_u, f[kEps1], unit_exponents);
  prelude.su = PowerOf(angles.sin_u, f[kEps1], unit_exponents);
  prelude.cv = PowerOf(angles.cos_v, f[kEps2], unit_exponents);
  prelude.sv = PowerOf(angles.sin_v, f[kEps2], unit_exponents);
  double x1 = f[kA1] * prelude.cu.value * prelude.cv.value;
  double x2 = f[kA2] * prelude.cu.value * prelude.sv.value;
  prelude.w = w;
  if (w != 0.0) {
    const Eigen::Vector3d m(angles.cos_u * angles.cos_v / f[kA1],
                            angles.cos_u * angles.sin_v / f[kA2],
                            angles.sin_u / f[kA3]);
    prelude.wall_inverse_norm = 1.0 / m.norm();
    prelude.wall_direction = m * prelude.wall_inverse_norm;
    const double half = WallDepth(f, w) / f[kA0];
    x1 += half * prelude.wall_direction[0];
    x2 += half * prelude.wall_direction[1];
  }
  prelude.angles[kPhase1] = kHalfPi * (x1 - f[kB1]);
  prelude.angles[kBend1] = kHalfPi * f[kB1];
  prelude.angles[kPhase2] = kHalfPi * (x2 - f[kB3]);
  prelude.angles[kBend2] = kHalfPi * f[kB3];
  prelude.angles[kTwist] = TwistAt(f, w);
  if (same_ring != nullptr) {
    std::copy(same_ring->j0, same_ring->j0 + 2, prelude.j0);
    std::copy(same_ring->j1, same_ring->j1 + 2, prelude.j1);
    return prelude;
  }
  for (int i = 0; i < 2; ++i) {
    const double ring = kHalfPi * f[i == 0 ? kA1 : kA2] * prelude.cu.value;
    const BesselJ01 j = BesselJ0J1(ring);
    prelude.j0[i] = j.j0;
    prelude.j1[i] = j.j1;
  }
  return prelude;
}

Eigen::Vector3d ShapeAndJacobian(const double* f, const Angles<double>& angles,
                                 bool unit_exponents, ShapeJacobian* jacobian,
                                 double w) {
  const ShapePrelude prelude = PrepareShape(f, angles, unit_exponents, w);
  double sines[kNumShapeAngles], cosines[kNumShapeAngles];
  for (int i = 0; i < kNumShapeAngles; ++i) {
    sines[i] = std::sin(prelude.angles[i]);
    cosines[i] = std::cos(prelude.angles[i]);
  }
  return ShapeAndJacobian(f, prelude, sines, cosines, jacobian);
}

// With e the primitive, b = T_b(e), t = Rz(tau) b and s = t + o:
//   ds/df = Rz (B_e de/df + db/df|_e) + dt/dtau + do/df,
// B_e = I + e3 (beta1, beta2, 0)^T, beta_i = b_{2i-2} g_x(e_i / a0, b_{2i-1}) /
// a0, g(x, b, r) = cos(pi/2 (x - b)) - J0(pi/2 r) cos(pi/2 b), and the ring
// half extents r1 = a1 Cu^e1, r2 = a2 Cu^e1 bring in
// dg/dr = pi/2 J1(pi/2 r) cos(pi/2 b) (J0' = -J1).  Off the mid-wall the
// primitive is e + k n with k = w h / 2 + w^2 s + (w^3 - w) q and n = m / |m|
// (transmural.h), so de/dh = w n / 2, de/ds = w^2 n, de/dq = (w^3 - w) n and
// de/da_i = k (I - n n^T)
// dm/da_i / |m| with dm/da_i = -m_i / a_i along axis i; the twist angle is tau
// + w dtau / 2.
Eigen::Vector3d ShapeAndJacobian(const double* f, const ShapePrelude& prelude,
                                 const double* sines, const double* cosines,
                                 ShapeJacobian* jacobian) {
  const Power &cu = prelude.cu, &su = prelude.su, &cv = prelude.cv,
              &sv = prelude.sv;
  const double a0 = f[kA0];
  const Eigen::Vector3d primitive(a0 * f[kA1] * cu.value * cv.value,
                                  a0 * f[kA2] * cu.value * sv.value,
                                  a0 * f[kA3] * su.value);
  const double half_wall = WallDepth(f, prelude.w);
  const Eigen::Vector3d e = primitive + half_wall * prelude.wall_direction;

  const double x1 = e[0] / a0;
  const double x2 = e[1] / a0;
  const double g1 = cosines[kPhase1] - prelude.j0[0] * cosines[kBend1];
  const double g2 = cosines[kPhase2] - prelude.j0[1] * cosines[kBend2];
  const Eigen::Vector3d b(e[0], e[1], e[2] + f[kB0] * g1 + f[kB2] * g2);

  const double c = cosines[kTwist], s = sines[kTwist];
  const Eigen::Vector3d t(c * b[0] - s * b[1], s * b[0] + c * b[1], b[2]);
  const Eigen::Vector3d shape = t + Eigen::Vector3d(f[kE1o], f[kE2o], f[kE3o]);
  if (jacobian == nullptr) return shape;

  // The columns that pass through e (a0..a3 and the exponents, and h and
  // the wall shift off the mid-wall) take the bend's coupling into z and
  // the twist alike: ds_j = T (B_e de_j).  The rest enter at one step
  // each.  Only the nonzero entries are computed; most of ds is zero.
  const double gx1 = -kHalfPi * sines[kPhase1];
  const double gx2 = -kHalfPi * sines[kPhase2];
  const double beta1 = f[kB0] * gx1 / a0, beta2 = f[kB2] * gx2 / a0;
  ShapeJacobian& ds = *jacobian;
  ds.setZero();
  auto through_e = [&](int j, double e0, double e1, double e2) {
    ds(0, j) = c * e0 - s * e1;
    ds(1, j) = s * e0 + c * e1;
    ds(2, j) = e2 + beta1 * e0 + beta2 * e1;
  };
  Eigen::Vector3d de_da[3] = {Eigen::Vector3d(a0 * cu.value * cv.value, 0, 0),
                              Eigen::Vector3d(0, a0 * cu.value * sv.value, 0),
                              Eigen::Vector3d(0, 0, a0 * su.value)};
  if (prelude.w != 0.0) {
    const Eigen::Vector3d& n = prelude.wall_direction;
    const Eigen::Matrix3d project =
        (Eigen::Matrix3d::Identity() - n * n.transpose()) *
        (half_wall * prelude.wall_inverse_norm);
    // m_i = n_i |m|, so dm_i/da_i = -n_i |m| / a_i.
    for (int i = 0; i < 3; ++i) {
      de_da[i] -=
          project.col(i) * (n[i] / (prelude.wall_inverse_norm * f[kA1 + i]));
    }
    const Eigen::Vector3d de_dh = 0.5 * prelude.w * n;
    const Eigen::Vector3d de_dshift = prelude.w * prelude.w * n;
    const Eigen::Vector3d de_dsqueeze =
        (prelude.w * prelude.w - 1.0) * prelude.w * n;
    through_e(kH, de_dh[0], de_dh[1], de_dh[2]);
    through_e(kWallShift, de_dshift[0], de_dshift[1], de_dshift[2]);
    through_e(kWallSqueeze, de_dsqueeze[0], de_dsqueeze[1], de_dsqueeze[2]);
  }
  const Eigen::Vector3d de_da0 = primitive / a0;
  through_e(kA0, de_da0[0], de_da0[1], de_da0[2]);
  for (int i = 0; i < 3; ++i) {
    through_e(kA1 + i, de_da[i][0], de_da[i][1], de_da[i][2]);
  }
  through_e(kEps1, a0 * f[kA1] * cu.d_exponent * cv.value,
            a0 * f[kA2] * cu.d_exponent * sv.value,
            a0 * f[kA3] * su.d_exponent);
  through_e(kEps2, a0 * f[kA1] * cu.value * cv.d_exponent,
            a0 * f[kA2] * cu.value * sv.d_exponent, 0.0);

  // The bend's own dependence on a0 (x_i = e_i / a0 with e_i held) and on
  // b0..b3, and the ring means through r1 = a1 Cu^e1 and r2 = a2 Cu^e1: z
  // only, which the twist leaves alone.
  ds(2, kA0) -= beta1 * x1 + beta2 * x2;
  ds(2, kB0) = g1;
  ds(2, kB1) =
      f[kB0] * kHalfPi * (sines[kPhase1] + prelude.j0[0] * sines[kBend1]);
  ds(2, kB2) = g2;
  ds(2, kB3) =
      f[kB2] * kHalfPi * (sines[kPhase2] + prelude.j0[1] * sines[kBend2]);
  const double gr1 = f[kB0] * kHalfPi * prelude.j1[0] * cosines[kBend1];
  const double gr2 = f[kB2] * kHalfPi * prelude.j1[1] * cosines[kBend2];
  ds(2, kA1) += gr1 * cu.value;
  ds(2, kA2) += gr2 * cu.value;
  ds(2, kEps1) += (gr1 * f[kA1] + gr2 * f[kA2]) * cu.d_exponent;

  // tau itself turns b; offsets add.
  ds(0, kTau) = -s * b[0] - c * b[1];
  ds(1, kTau) = c * b[0] - s * b[1];
  ds(0, kDtau) = 0.5 * prelude.w * ds(0, kTau);
  ds(1, kDtau) = 0.5 * prelude.w * ds(1, kTau);
  ds(0, kE1o) = 1.0;
  ds(1, kE2o) = 1.0;
  ds(2, kE3o) = 1.0;
  return shape;
}

}  // namespace pfdm
