// Lagrangian strain of a deforming surface's tangent plane: the regional
// strains Ecc, Ell and Ecl that tagged MRI reports, measured on material
// points of the fitted model (or of any surface whose points are tracked).
#ifndef PFDM_REPORT_SURFACE_STRAIN_H_
#define PFDM_REPORT_SURFACE_STRAIN_H_

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// Green-Lagrange strain components (fractions, not percent) in the
// reference plane's circumferential / longitudinal basis.
struct SurfaceStrain {
  double ecc = 0.0;
  double ell = 0.0;
  double ecl = 0.0;
};

// Two reference tangent vectors a0, b0 (any pair spanning the plane, e.g.
// X_u and X_v, or a triangle's edges) deform to a, b.  The strain is
// reported in the orthonormal basis (e_c, e_l) of the reference plane:
// e_c along `circumferential` projected on the plane, e_l perpendicular to
// e_c in the plane, on the side of `longitudinal` (apex to base).
//
// With G the 2x2 matrix whose columns are a0 and b0 in (e_c, e_l), the
// surface deformation gradient is F = [a b] G^-1 (3x2), so
//   C = F^T F = G^-T g G^-1,  g = [a.a a.b; a.b b.b]  (frame t's metric),
//   E = (C - I) / 2;  Ecc = E_00, Ell = E_11, Ecl = E_01.
// Only the metric of the deformed vectors enters: a rigid motion of the
// deformed surface changes nothing.
SurfaceStrain PlaneStrain(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& circumferential,
                          const Eigen::Vector3d& longitudinal);

// PlaneStrain in two halves, for a reference plane compared with many
// deformed ones (the delta method's steps, number_uncertainty.h): G^-1 of
// the reference's, then the strain of the deformed vectors a, b.  The same
// arithmetic, so the same bits, as PlaneStrain.
Eigen::Matrix2d ReferencePlaneInverse(const Eigen::Vector3d& a0,
                                      const Eigen::Vector3d& b0,
                                      const Eigen::Vector3d& circumferential,
                                      const Eigen::Vector3d& longitudinal);
SurfaceStrain PlaneStrain(const Eigen::Matrix2d& reference_inverse,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// The strain at material point (u, v) of `current` against `reference`
// (frame 0): tangents X_u, X_v (SurfaceTangents);
// e_c along X_v (v counter-clockwise about the model's +z), e_l toward
// increasing u, from the apex to the base.  Not defined at the apex pole,
// where X_v vanishes.
// The world-frame tangents dx/du, dx/dv at (u, v) of the mid-wall, as
// StrainAt takes them: the global shape's in closed form
// (ShapeAngleDerivatives), the local field's through ceres::Jet.  On a
// knot, the mean of its two spans' slopes (RingFunctions); on an edge of
// the local field's elements, one side's.
void SurfaceTangents(const Model& model, double u, double v,
                     Eigen::Vector3d* xu, Eigen::Vector3d* xv);

// What SurfaceTangents needs of ring u's functions, for the ring's samples
// to share: on a knot, `slopes` is the mean of its two spans'.
struct RingFunctions {
  RingFunctions(const Model& model, double u);
  double u;
  FunctionValues at, slopes;  // FunctionsAt(u), FunctionSlopesAt(u).
};
void SurfaceTangents(const Model& model, const RingFunctions& ring, double v,
                     Eigen::Vector3d* xu, Eigen::Vector3d* xv);
// The same on a solid's surface w (transmural.h), as the layers' strain
// reads each layer.
void SurfaceTangents(const Model& model, const RingFunctions& ring, double v,
                     double w, Eigen::Vector3d* xu, Eigen::Vector3d* xv);
// The same at the ring's n points v[j] into xu[j], xv[j], to the bit: the
// global shape's for the whole ring at once (ShapeAngleDerivativesAlong).
void SurfaceTangentsAlong(const Model& model, const RingFunctions& ring,
                          const double* v, int n, double w, Eigen::Vector3d* xu,
                          Eigen::Vector3d* xv);

SurfaceStrain StrainAt(const Model& reference, const Model& current, double u,
                       double v);

}  // namespace pfdm

#endif  // PFDM_REPORT_SURFACE_STRAIN_H_
