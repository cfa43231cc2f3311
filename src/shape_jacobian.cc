#include "pfdm/shape_jacobian.h"

#include <cmath>

namespace pfdm {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

// SignedPower and its derivative in the exponent:
// d/de [x (x^2 + d^2)^((e-1)/2)] = SignedPower(x, e) ln(x^2 + d^2) / 2.
struct Power {
  double value;
  double d_exponent;
};

// sin and cos of one angle in one libm call.
struct SinCos {
  explicit SinCos(double angle) { ::sincos(angle, &sin, &cos); }
  double sin, cos;
};

Power PowerOf(double x, double e, bool unit_exponents) {
  if (unit_exponents) return {x, 0.0};
  const double base = x * x + kSignedPowerDelta * kSignedPowerDelta;
  const double value = SignedPower(x, e);
  return {value, 0.5 * value * std::log(base)};
}

}  // namespace

// With e the primitive, b = T_b(e), t = Rz(tau) b and s = t + o:
//   ds/df = Rz (B_e de/df + db/df|_e) + dt/dtau + do/df,
// B_e = I + e3 (beta1, beta2, 0)^T, beta_i = b_{2i-2} g_x(e_i / a0, b_{2i-1}) /
// a0, g(x, b) = cos(pi/2 (x - b)) - cos(pi/2 b).
Eigen::Vector3d ShapeAndJacobian(const double* f, const Angles<double>& angles,
                                 bool unit_exponents, ShapeJacobian* jacobian) {
  const Power cu = PowerOf(angles.cos_u, f[kEps1], unit_exponents);
  const Power su = PowerOf(angles.sin_u, f[kEps1], unit_exponents);
  const Power cv = PowerOf(angles.cos_v, f[kEps2], unit_exponents);
  const Power sv = PowerOf(angles.sin_v, f[kEps2], unit_exponents);
  const double a0 = f[kA0];
  const Eigen::Vector3d e(a0 * f[kA1] * cu.value * cv.value,
                          a0 * f[kA2] * cu.value * sv.value,
                          a0 * f[kA3] * su.value);

  const double x1 = e[0] / a0, x2 = e[1] / a0;
  const SinCos phase1(kHalfPi * (x1 - f[kB1])), shape1(kHalfPi * f[kB1]);
  const SinCos phase2(kHalfPi * (x2 - f[kB3])), shape2(kHalfPi * f[kB3]);
  const double g1 = phase1.cos - shape1.cos;
  const double g2 = phase2.cos - shape2.cos;
  const Eigen::Vector3d b(e[0], e[1], e[2] + f[kB0] * g1 + f[kB2] * g2);

  const SinCos twist(f[kTau]);
  const double c = twist.cos, s = twist.sin;
  const Eigen::Vector3d t(c * b[0] - s * b[1], s * b[0] + c * b[1], b[2]);
  const Eigen::Vector3d shape = t + Eigen::Vector3d(f[kE1o], f[kE2o], f[kE3o]);
  if (jacobian == nullptr) return shape;

  // de/df: only a0, a1..a3 and the exponents enter the primitive.
  Eigen::Matrix<double, 3, kNumFunctions> de =
      Eigen::Matrix<double, 3, kNumFunctions>::Zero();
  de.col(kA0) = e / a0;
  de(0, kA1) = a0 * cu.value * cv.value;
  de(1, kA2) = a0 * cu.value * sv.value;
  de(2, kA3) = a0 * su.value;
  de(0, kEps1) = a0 * f[kA1] * cu.d_exponent * cv.value;
  de(1, kEps1) = a0 * f[kA2] * cu.d_exponent * sv.value;
  de(2, kEps1) = a0 * f[kA3] * su.d_exponent;
  de(0, kEps2) = a0 * f[kA1] * cu.value * cv.d_exponent;
  de(1, kEps2) = a0 * f[kA2] * cu.value * sv.d_exponent;

  // db/df = B_e de/df + the bend's own dependence on a0 and b0..b3.
  const double gx1 = -kHalfPi * phase1.sin;
  const double gx2 = -kHalfPi * phase2.sin;
  const double beta1 = f[kB0] * gx1 / a0, beta2 = f[kB2] * gx2 / a0;
  Eigen::Matrix<double, 3, kNumFunctions> db = de;
  db.row(2) += beta1 * de.row(0) + beta2 * de.row(1);
  db(2, kA0) -= beta1 * x1 + beta2 * x2;  // x_i = e_i / a0 with e_i held.
  db(2, kB0) += g1;
  db(2, kB1) += f[kB0] * kHalfPi * (phase1.sin + shape1.sin);
  db(2, kB2) += g2;
  db(2, kB3) += f[kB2] * kHalfPi * (phase2.sin + shape2.sin);

  // Twist rotates the first two rows; tau itself turns b; offsets add.
  ShapeJacobian& ds = *jacobian;
  ds.row(0) = c * db.row(0) - s * db.row(1);
  ds.row(1) = s * db.row(0) + c * db.row(1);
  ds.row(2) = db.row(2);
  ds(0, kTau) += -s * b[0] - c * b[1];
  ds(1, kTau) += c * b[0] - s * b[1];
  ds(0, kE1o) += 1.0;
  ds(1, kE2o) += 1.0;
  ds(2, kE3o) += 1.0;
  return shape;
}

}  // namespace pfdm
