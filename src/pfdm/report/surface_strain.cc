#include "pfdm/report/surface_strain.h"

#include "Eigen/Dense"

namespace pfdm {
namespace {

// Step in u and v: small against the knot spacing (about 0.13 for 17
// knots), large against rounding (positions ~ 100 mm, 1e-16 relative).
constexpr double kStep = 1e-5;

}  // namespace

SurfaceStrain PlaneStrain(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& circumferential,
                          const Eigen::Vector3d& longitudinal) {
  const Eigen::Vector3d normal = a0.cross(b0).normalized();
  const Eigen::Vector3d e_c =
      (circumferential - circumferential.dot(normal) * normal).normalized();
  Eigen::Vector3d e_l = normal.cross(e_c);
  if (e_l.dot(longitudinal) < 0) e_l = -e_l;
  Eigen::Matrix2d g0;  // Columns: a0, b0 in (e_c, e_l).
  g0 << e_c.dot(a0), e_c.dot(b0), e_l.dot(a0), e_l.dot(b0);
  Eigen::Matrix2d metric;
  metric << a.dot(a), a.dot(b), a.dot(b), b.dot(b);
  const Eigen::Matrix2d inverse = g0.inverse();
  const Eigen::Matrix2d e = 0.5 * (inverse.transpose() * metric * inverse -
                                   Eigen::Matrix2d::Identity());
  return {e(0, 0), e(1, 1), 0.5 * (e(0, 1) + e(1, 0))};
}

RingFunctions::RingFunctions(const Model& model, double u)
    : u(u),
      below(model.FunctionsAt(u - kStep)),
      at(model.FunctionsAt(u)),
      above(model.FunctionsAt(u + kStep)) {}

void SurfaceTangents(const Model& model, const RingFunctions& ring, double v,
                     Eigen::Vector3d* xu, Eigen::Vector3d* xv) {
  const double u = ring.u;
  *xu = (model.WorldPointWith(ring.above, u + kStep, v) -
         model.WorldPointWith(ring.below, u - kStep, v)) /
        (2 * kStep);
  *xv = (model.WorldPointWith(ring.at, u, v + kStep) -
         model.WorldPointWith(ring.at, u, v - kStep)) /
        (2 * kStep);
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
