#include "pfdm/report/surface_strain.h"

#include <vector>

#include "Eigen/Dense"
#include "ceres/jet.h"
#include "pfdm/model/local_field.h"
#include "pfdm/model/shape_angle_derivative.h"

namespace pfdm {

Eigen::Matrix2d ReferencePlaneInverse(const Eigen::Vector3d& a0,
                                      const Eigen::Vector3d& b0,
                                      const Eigen::Vector3d& circumferential,
                                      const Eigen::Vector3d& longitudinal) {
  const Eigen::Vector3d normal = a0.cross(b0).normalized();
  const Eigen::Vector3d e_c =
      (circumferential - circumferential.dot(normal) * normal).normalized();
  Eigen::Vector3d e_l = normal.cross(e_c);
  if (e_l.dot(longitudinal) < 0) e_l = -e_l;
  Eigen::Matrix2d g0;  // Columns: a0, b0 in (e_c, e_l).
  g0 << e_c.dot(a0), e_c.dot(b0), e_l.dot(a0), e_l.dot(b0);
  return g0.inverse();
}

SurfaceStrain PlaneStrain(const Eigen::Matrix2d& reference_inverse,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Matrix2d metric;
  metric << a.dot(a), a.dot(b), a.dot(b), b.dot(b);
  const Eigen::Matrix2d& inverse = reference_inverse;
  const Eigen::Matrix2d e = 0.5 * (inverse.transpose() * metric * inverse -
                                   Eigen::Matrix2d::Identity());
  return {e(0, 0), e(1, 1), 0.5 * (e(0, 1) + e(1, 0))};
}

SurfaceStrain PlaneStrain(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& circumferential,
                          const Eigen::Vector3d& longitudinal) {
  return PlaneStrain(
      ReferencePlaneInverse(a0, b0, circumferential, longitudinal), a, b);
}

namespace {

// How far either side of u the slopes are taken: within a knot span they
// are the same on both sides, to the bit.
constexpr double kKnotSide = 1e-9;

// d f / du at u, and on a knot (where the functions bend) the mean of the
// two spans' slopes: a ring's samples stand for a band across it, half in
// each span.  Regional samples at equal steps of sin u fall on the knots,
// which lie at equal steps of sin u too (wall_motion's 60 rings: 7, 22, 37
// and 52 with 17 knots).
FunctionValues SlopesAcross(const Model& model, double u) {
  const FunctionValues below = model.FunctionSlopesAt(u - kKnotSide);
  const FunctionValues above = model.FunctionSlopesAt(u + kKnotSide);
  FunctionValues slopes;
  for (size_t i = 0; i < slopes.size(); ++i) {
    slopes[i] = 0.5 * (below[i] + above[i]);
  }
  return slopes;
}

}  // namespace

RingFunctions::RingFunctions(const Model& model, double u)
    : u(u), at(model.FunctionsAt(u)), slopes(SlopesAcross(model, u)) {}

void SurfaceTangents(const Model& model, const RingFunctions& ring, double v,
                     Eigen::Vector3d* xu, Eigen::Vector3d* xv) {
  SurfaceTangents(model, ring, v, 0.0, xu, xv);
}

namespace {

// R (d_shape + d_local) along u and v at (ring.u, v) on surface w.
void WorldTangents(const Model& model, const RingFunctions& ring, double v,
                   double w, const ShapeAndAngleDerivatives& shape,
                   const Eigen::Matrix3d& rotation, Eigen::Vector3d* xu,
                   Eigen::Vector3d* xv) {
  using Jet2 = ceres::Jet<double, 2>;
  const Eigen::Matrix<Jet2, 3, 1> local =
      LocalDisplacement(model.state.local, Jet2(ring.u, 0), Jet2(v, 1), w);
  Eigen::Vector3d local_u, local_v;
  for (int i = 0; i < 3; ++i) {
    local_u[i] = local[i].v[0];
    local_v[i] = local[i].v[1];
  }
  *xu = rotation * (shape.d_u + local_u);
  *xv = rotation * (shape.d_v + local_v);
}

}  // namespace

void SurfaceTangents(const Model& model, const RingFunctions& ring, double v,
                     double w, Eigen::Vector3d* xu, Eigen::Vector3d* xv) {
  const ShapeAndAngleDerivatives shape = ShapeAngleDerivatives(
      ring.at.data(), ring.slopes.data(), ring.u, v, model.UnitExponents(), w);
  WorldTangents(model, ring, v, w, shape, model.Rotation(), xu, xv);
}

void SurfaceTangentsAlong(const Model& model, const RingFunctions& ring,
                          const double* v, int n, double w, Eigen::Vector3d* xu,
                          Eigen::Vector3d* xv) {
  std::vector<ShapeAndAngleDerivatives> shapes(n);
  ShapeAngleDerivativesAlong(ring.at.data(), ring.slopes.data(), ring.u, v, n,
                             model.UnitExponents(), w, shapes.data());
  const Eigen::Matrix3d rotation = model.Rotation();
  for (int j = 0; j < n; ++j) {
    WorldTangents(model, ring, v[j], w, shapes[j], rotation, &xu[j], &xv[j]);
  }
}

void SurfaceTangents(const Model& model, double u, double v,
                     Eigen::Vector3d* xu, Eigen::Vector3d* xv) {
  SurfaceTangents(model, RingFunctions(model, u), v, xu, xv);
}

SurfaceStrain StrainAt(const Model& reference, const Model& current, double u,
                       double v) {
  Eigen::Vector3d xu0, xv0, xu, xv;
  SurfaceTangents(reference, u, v, &xu0, &xv0);
  SurfaceTangents(current, u, v, &xu, &xv);
  return PlaneStrain(xu0, xv0, xu, xv, xv0, xu0);
}

}  // namespace pfdm
