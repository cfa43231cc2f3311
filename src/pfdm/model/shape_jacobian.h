// The reference shape s(f; u, v) and its Jacobian ds/df in closed form: the
// chain J = dT_o/dt dT_twist/db dT_b/de de/df of the paper, term by term.
#ifndef PFDM_MODEL_SHAPE_JACOBIAN_H_
#define PFDM_MODEL_SHAPE_JACOBIAN_H_

#include <algorithm>

#include "Eigen/Core"
#include "pfdm/model/parameter_function.h"
#include "pfdm/model/superellipsoid.h"
#include "pfdm/util/batch_trig.h"

namespace pfdm {

using ShapeJacobian = Eigen::Matrix<double, 3, kNumFunctions>;

// A signed power (superellipsoid.h) and its derivative in the exponent.
struct Power {
  double value;
  double d_exponent;
};

// What the shape needs before any sine or cosine of fitted functions: the
// primitive's powers and the five angles (the two bends' phases and shapes,
// the twist) whose sines and cosines follow.  Split off so that a group of
// points can take its trigonometry in one batch (batch_trig.h).
constexpr int kNumShapeAngles = 5;
struct ShapePrelude {
  Power cu, su, cv, sv;
  double angles[kNumShapeAngles];
  // J0 and J1 at pi/2 times each ring half extent (the bends' ring means).
  double j0[2], j1[2];
  // The surface w (transmural.h): w, the wall direction n and 1 / |m|.
  double w = 0.0;
  Eigen::Vector3d wall_direction = Eigen::Vector3d::Zero();
  double wall_inverse_norm = 0.0;
};
// With same_ring, a prelude of the same a1, a2 and Cu^e1 (a point of the
// same ring), its Bessel values are taken, not computed again: the
// surfaces and grids are sampled ring by ring, and J0 and J1 were a tenth
// of a contour job.
ShapePrelude PrepareShape(const double* f, const Angles<double>& angles,
                          bool unit_exponents, double w = 0.0,
                          const ShapePrelude* same_ring = nullptr);

// Whether points (f, angles) and (g, other) have the same ring half extents
// a1 Cu^e1 and a2 Cu^e1, bit for bit.
inline bool SameRing(const double* f, const Angles<double>& angles,
                     const double* g, const Angles<double>& other) {
  return angles.cos_u == other.cos_u && f[kA1] == g[kA1] && f[kA2] == g[kA2] &&
         f[kEps1] == g[kEps1];
}

// The shape and, when jacobian is not null, ds/df, from the prelude and the
// sines and cosines of its angles.
Eigen::Vector3d ShapeAndJacobian(const double* f, const ShapePrelude& prelude,
                                 const double* sines, const double* cosines,
                                 ShapeJacobian* jacobian);

// The shapes of `count` <= kShapeBatch points, their sines and cosines in
// one SinCosMany (batch_trig.h): for each i < count, in turn, calls
// visit(i, s, ds) with s the shape for f[i] at angles[i] on surface w[i]
// and, if with_jacobian, ds = ds/df (else ds is not set).
constexpr int kShapeBatch = 32;
template <typename Visit>
void ShapesOfBatch(int count, const FunctionValues* f,
                   const Angles<double>* angles, const double* w,
                   bool unit_exponents, bool with_jacobian, Visit visit) {
  ShapePrelude preludes[kShapeBatch];
  double shape_angles[kShapeBatch * kNumShapeAngles] = {};
  double sines[kShapeBatch * kNumShapeAngles];
  double cosines[kShapeBatch * kNumShapeAngles];
  for (int i = 0; i < count; ++i) {
    const bool same_ring = i > 0 && SameRing(f[i].data(), angles[i],
                                             f[i - 1].data(), angles[i - 1]);
    preludes[i] = PrepareShape(f[i].data(), angles[i], unit_exponents, w[i],
                               same_ring ? &preludes[i - 1] : nullptr);
    std::copy(preludes[i].angles, preludes[i].angles + kNumShapeAngles,
              shape_angles + i * kNumShapeAngles);
  }
  SinCosMany(shape_angles, count * kNumShapeAngles, sines, cosines);
  ShapeJacobian ds;
  for (int i = 0; i < count; ++i) {
    const int at = i * kNumShapeAngles;
    const Eigen::Vector3d s =
        ShapeAndJacobian(f[i].data(), preludes[i], sines + at, cosines + at,
                         with_jacobian ? &ds : nullptr);
    visit(i, s, ds);
  }
}

// Returns s = T_o(T_twist(T_b(e))) for the function values f at the
// material point with the given angles on surface w and, when jacobian is
// not null, ds/df (3 x kNumFunctions, one column per function).  Matches
// ReferenceShape.
Eigen::Vector3d ShapeAndJacobian(const double* f, const Angles<double>& angles,
                                 bool unit_exponents, ShapeJacobian* jacobian,
                                 double w = 0.0);

}  // namespace pfdm

#endif  // PFDM_MODEL_SHAPE_JACOBIAN_H_
