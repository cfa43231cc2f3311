// The reference shape's derivatives along the material coordinates (u, v),
// in closed form: what the closest-point search steps on.
#ifndef PFDM_MODEL_SHAPE_ANGLE_DERIVATIVE_H_
#define PFDM_MODEL_SHAPE_ANGLE_DERIVATIVE_H_

#include "Eigen/Core"

namespace pfdm {

struct ShapeAndAngleDerivatives {
  Eigen::Vector3d shape;  // s, model frame, as ReferenceShape.
  Eigen::Vector3d d_u;    // ds/du, the functions moving along u too.
  Eigen::Vector3d d_v;    // ds/dv.
};

// s = T_o(T_twist(T_b(e))) for the function values f at the material point
// (u, v), and its total derivatives in u and v when the functions change
// along u at the rates df_du (the knot span's slopes of the free functions,
// 0 for the others).  Matches ReferenceShape differentiated in its angles
// with ceres::Jet (tested), at a fraction of the cost; on surface w
// (transmural.h) off the mid-wall too.  The sines and cosines of u, v and
// the twist come from one SinCosMany batch (libmvec's four lanes, within
// its 4 ulp), a bent model's four bend angles from another: the
// closest-point search evaluates this at every step, where up to seven
// scalar sincos were an eighth of its time.
ShapeAndAngleDerivatives ShapeAngleDerivatives(const double* f,
                                               const double* df_du, double u,
                                               double v, bool unit_exponents,
                                               double w = 0.0);

// ShapeAngleDerivatives at (u, v[j]) for j < n into out[j], the same to the
// bit: the sines and cosines of u and of the twist are taken once, the
// v's in one batch (an angle's SinCosMany bits do not depend on its place
// in the batch).  The measurements' rows of samples at one u (wall_motion)
// took a fifth of `--uncertainty on` one point at a time.
void ShapeAngleDerivativesAlong(const double* f, const double* df_du, double u,
                                const double* v, int n, bool unit_exponents,
                                double w, ShapeAndAngleDerivatives* out);

}  // namespace pfdm

#endif  // PFDM_MODEL_SHAPE_ANGLE_DERIVATIVE_H_
