#include "pfdm/model/shape_angle_derivative.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "pfdm/model/parameter_function.h"
#include "pfdm/model/signed_power.h"
#include "pfdm/model/superellipsoid.h"
#include "pfdm/model/transmural.h"
#include "pfdm/util/batch_trig.h"
#include "pfdm/util/bessel.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

// A value with its derivatives in u and v.
struct Graded {
  double value, d_u, d_v;
};

struct CosSin {
  double cos, sin;
};

// sgn(x)|x|^e as SignedPower, x and e graded.
Graded GradedSignedPower(const Graded& x, double e, double de_du) {
  const double base = x.value * x.value + kSignedPowerDelta * kSignedPowerDelta;
  const double power = std::pow(base, (e - 1.0) * 0.5);
  const double value = x.value * power;
  // d/dx = base^((e-3)/2) (e x^2 + delta^2); d/de = value ln(base) / 2.
  const double d_x =
      power / base *
      (e * x.value * x.value + kSignedPowerDelta * kSignedPowerDelta);
  const double d_e = 0.5 * value * std::log(base);
  return {value, d_x * x.d_u + d_e * de_du, d_x * x.d_v};
}

// Whether the bend of this amplitude (kB0 or kB2) moves the shape here:
// not while the amplitude and its slope are zero (frame 0, and any unbent
// model).
bool Bends(const double* f, const double* df_du, int amplitude) {
  return f[amplitude] != 0.0 || df_du[amplitude] != 0.0;
}

// b g(x, b, r) of global_deformations.h's BendProfile with its derivatives,
// given the cosines and sines of its phase h (x - b) and of h b, h = pi / 2
// (b's own value enters only through them).
Graded GradedBend(double amplitude, double d_amplitude, const Graded& x,
                  double db_du, double r, double dr_du, CosSin phase_trig,
                  CosSin b_trig) {
  if (amplitude == 0.0 && d_amplitude == 0.0) return {0.0, 0.0, 0.0};
  const double cos_phase = phase_trig.cos, sin_phase = phase_trig.sin;
  const double cos_b = b_trig.cos, sin_b = b_trig.sin;
  const BesselJ01 j = BesselJ0J1(kHalfPi * r);
  const double j0 = j.j0, j1 = j.j1;
  const double g = cos_phase - j0 * cos_b;
  // dg = -h sin(h (x - b)) (dx - db) + h J1(h r) cos(h b) dr
  //      + h J0(h r) sin(h b) db, h = pi / 2.
  const double dg_du = kHalfPi * (-sin_phase * (x.d_u - db_du) +
                                  j1 * cos_b * dr_du + j0 * sin_b * db_du);
  const double dg_dv = -kHalfPi * sin_phase * x.d_v;
  return {amplitude * g, d_amplitude * g + amplitude * dg_du,
          amplitude * dg_dv};
}

// k n of transmural.h's WallOffset, graded: n = m / |m| with m =
// (cos u cos v / a1, cos u sin v / a2, sin u / a3) and dn = (I - n n^T) dm /
// |m|; k = WallDepth, which moves along u with the functions' slopes.
std::array<Graded, 3> GradedWallOffset(const double* f, const double* df_du,
                                       const Angles<double>& angles, double w) {
  const double cu = angles.cos_u, su = angles.sin_u;
  const double cv = angles.cos_v, sv = angles.sin_v;
  const Eigen::Vector3d a(f[kA1], f[kA2], f[kA3]);
  const Eigen::Vector3d da(df_du[kA1], df_du[kA2], df_du[kA3]);
  const Eigen::Vector3d top(cu * cv, cu * sv, su);
  const Eigen::Vector3d top_u(-su * cv, -su * sv, cu);
  const Eigen::Vector3d top_v(-cu * sv, cu * cv, 0.0);
  const Eigen::Vector3d m = top.cwiseQuotient(a);
  const Eigen::Vector3d m_u =
      top_u.cwiseQuotient(a) - m.cwiseProduct(da).cwiseQuotient(a);
  const Eigen::Vector3d m_v = top_v.cwiseQuotient(a);
  const double norm = m.norm();
  const Eigen::Vector3d n = m / norm;
  const Eigen::Vector3d n_u = (m_u - n * n.dot(m_u)) / norm;
  const Eigen::Vector3d n_v = (m_v - n * n.dot(m_v)) / norm;
  const double k = WallDepth(f, w), k_u = WallDepth(df_du, w);
  std::array<Graded, 3> offset;
  for (int i = 0; i < 3; ++i) {
    offset[i] = {k * n[i], k_u * n[i] + k * n_u[i], k * n_v[i]};
  }
  return offset;
}

Graded Plus(const Graded& a, const Graded& b) {
  return {a.value + b.value, a.d_u + b.d_u, a.d_v + b.d_v};
}

// Tau on surface w (TwistAt), or its slope when f holds the slopes; on the
// mid-wall f's own entry, exactly.
double TwistOf(const double* f, double w) {
  return w == 0.0 ? f[kTau] : TwistAt(f, w);
}

// ShapeAngleDerivatives with the twist's cosine and sine given.  The bends'
// four come from one SinCosMany batch: scalar, they were four of a bent
// model's seven sincos per evaluation.
ShapeAndAngleDerivatives Derivatives(const double* f, const double* df_du,
                                     const Angles<double>& angles, CosSin twist,
                                     bool unit_exponents, double w) {
  // The primitive's signed powers of the angles' sines and cosines.
  const Graded cos_u{angles.cos_u, -angles.sin_u, 0.0};
  const Graded sin_u{angles.sin_u, angles.cos_u, 0.0};
  const Graded cos_v{angles.cos_v, 0.0, -angles.sin_v};
  const Graded sin_v{angles.sin_v, 0.0, angles.cos_v};
  Graded cu = cos_u, su = sin_u, cv = cos_v, sv = sin_v;
  if (!unit_exponents) {
    cu = GradedSignedPower(cos_u, f[kEps1], df_du[kEps1]);
    su = GradedSignedPower(sin_u, f[kEps1], df_du[kEps1]);
    cv = GradedSignedPower(cos_v, f[kEps2], df_du[kEps2]);
    sv = GradedSignedPower(sin_v, f[kEps2], df_du[kEps2]);
  }
  // e = a0 (a1 cu cv, a2 cu sv, a3 su).
  const double a0 = f[kA0], da0 = df_du[kA0];
  const auto radial = [&](int a, const Graded& around) {
    const double amplitude = a0 * f[a];
    const double d_amplitude = da0 * f[a] + a0 * df_du[a];
    return Graded{
        amplitude * cu.value * around.value,
        d_amplitude * cu.value * around.value +
            amplitude * (cu.d_u * around.value + cu.value * around.d_u),
        amplitude * cu.value * around.d_v};
  };
  Graded e1 = radial(kA1, cv);
  Graded e2 = radial(kA2, sv);
  Graded e3{a0 * f[kA3] * su.value,
            (da0 * f[kA3] + a0 * df_du[kA3]) * su.value + a0 * f[kA3] * su.d_u,
            0.0};
  // Off the mid-wall: the surface w's primitive, e + k n (transmural.h).
  if (w != 0.0) {
    const std::array<Graded, 3> offset = GradedWallOffset(f, df_du, angles, w);
    e1 = Plus(e1, offset[0]);
    e2 = Plus(e2, offset[1]);
    e3 = Plus(e3, offset[2]);
  }
  // Bending: across-axis positions in units of e1max = a0, ring half
  // extents a1 cu and a2 cu.
  const auto across = [&](const Graded& e) {
    return Graded{e.value / a0, (e.d_u * a0 - e.value * da0) / (a0 * a0),
                  e.d_v / a0};
  };
  Graded bend1{0.0, 0.0, 0.0}, bend2{0.0, 0.0, 0.0};
  if (Bends(f, df_du, kB0) || Bends(f, df_du, kB2)) {
    const Graded x1 = across(e1), x2 = across(e2);
    const double bend_angles[4] = {kHalfPi * (x1.value - f[kB1]),
                                   kHalfPi * (x2.value - f[kB3]),
                                   kHalfPi * f[kB1], kHalfPi * f[kB3]};
    double sines[4], cosines[4];
    SinCosMany(bend_angles, 4, sines, cosines);
    bend1 = GradedBend(f[kB0], df_du[kB0], x1, df_du[kB1], f[kA1] * cu.value,
                       df_du[kA1] * cu.value + f[kA1] * cu.d_u,
                       {cosines[0], sines[0]}, {cosines[2], sines[2]});
    bend2 = GradedBend(f[kB2], df_du[kB2], x2, df_du[kB3], f[kA2] * cu.value,
                       df_du[kA2] * cu.value + f[kA2] * cu.d_u,
                       {cosines[1], sines[1]}, {cosines[3], sines[3]});
  }
  const Graded bent3{e3.value + bend1.value + bend2.value,
                     e3.d_u + bend1.d_u + bend2.d_u,
                     e3.d_v + bend1.d_v + bend2.d_v};
  // Twist by the surface's tau about axis 3, then the offsets.
  const double c = twist.cos, s = twist.sin;
  const double dtau = TwistOf(df_du, w);
  ShapeAndAngleDerivatives out;
  out.shape = Eigen::Vector3d(c * e1.value - s * e2.value + f[kE1o],
                              s * e1.value + c * e2.value + f[kE2o],
                              bent3.value + f[kE3o]);
  out.d_u =
      Eigen::Vector3d(c * e1.d_u - s * e2.d_u -
                          dtau * (s * e1.value + c * e2.value) + df_du[kE1o],
                      s * e1.d_u + c * e2.d_u +
                          dtau * (c * e1.value - s * e2.value) + df_du[kE2o],
                      bent3.d_u + df_du[kE3o]);
  out.d_v = Eigen::Vector3d(c * e1.d_v - s * e2.d_v, s * e1.d_v + c * e2.d_v,
                            bent3.d_v);
  return out;
}

}  // namespace

ShapeAndAngleDerivatives ShapeAngleDerivatives(const double* f,
                                               const double* df_du, double u,
                                               double v, bool unit_exponents,
                                               double w) {
  const double angles[3] = {u, v, TwistOf(f, w)};
  double sines[3], cosines[3];
  SinCosMany(angles, 3, sines, cosines);
  return Derivatives(f, df_du, {cosines[0], sines[0], cosines[1], sines[1]},
                     {cosines[2], sines[2]}, unit_exponents, w);
}

void ShapeAngleDerivativesAlong(const double* f, const double* df_du, double u,
                                const double* v, int n, bool unit_exponents,
                                double w, ShapeAndAngleDerivatives* out) {
  std::vector<double> angles(n + 2), sines(n + 2), cosines(n + 2);
  angles[0] = u;
  angles[1] = TwistOf(f, w);
  std::copy(v, v + n, angles.begin() + 2);
  SinCosMany(angles.data(), n + 2, sines.data(), cosines.data());
  for (int j = 0; j < n; ++j) {
    out[j] = Derivatives(f, df_du,
                         {cosines[0], sines[0], cosines[j + 2], sines[j + 2]},
                         {cosines[1], sines[1]}, unit_exponents, w);
  }
}

}  // namespace pfdm
