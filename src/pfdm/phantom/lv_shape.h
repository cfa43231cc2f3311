// The end-diastolic shape of the analytic LV phantom: a shell between two
// confocal prolate spheroids, truncated by a plane at the base.
//
// Written from the prolate spheroidal coordinates (mu, nu, phi) of the
// cardiac-mechanics literature, not from pfdm's model: nothing here includes
// model/, so a phantom built on it can show where the model's own equations
// (its gauge, its parameter functions) are wrong.
//
// Body frame: the mid-wall apex pole at the origin, +z from apex to base.
// With a = d cosh(mu_mid) the mid-wall's semi-major axis,
//   x = d sinh(mu) sin(nu) cos(phi),  y = ... sin(phi),
//   z = a - d cosh(mu) cos(nu),
// nu = 0 the apex pole of every surface. The transmural position w runs
// -1 (endocardium) .. 0 (mid-wall) .. +1 (epicardium), linear in mu:
// mu = mu_mid + w dmu. All three surfaces stop at the plane z = length_mm.
#ifndef PFDM_PHANTOM_LV_SHAPE_H_
#define PFDM_PHANTOM_LV_SHAPE_H_

#include "Eigen/Core"

namespace pfdm {

struct LvShapeSize {
  double length_mm = 95.0;   // Mid-wall, apex pole to the base plane.
  double radius_mm = 27.0;   // Mid-wall at its widest (the equator).
  double wall_mm = 10.0;     // Epi minus endo radius at the equator.
  double base_nu_deg = 120;  // Mid-wall's nu at the base plane.
};

class LvShape {
 public:
  explicit LvShape(const LvShapeSize& size = LvShapeSize());

  const LvShapeSize& size() const { return size_; }
  double focal_mm() const { return d_; }
  double mu_mid() const { return mu_mid_; }
  double dmu() const { return dmu_; }
  double base_z() const { return length_; }  // Height of the base plane.

  double Mu(double w) const { return mu_mid_ + w * dmu_; }
  // Body position of (nu, phi) on surface w.
  Eigen::Vector3d Position(double nu, double phi, double w) const;
  // Surface w's apex pole height (negative on the epicardium) and its nu
  // at height z (clamped to [0, pi]).
  double ApexZ(double w) const;
  double NuAtHeight(double z, double w) const;
  double BaseNu(double w) const { return NuAtHeight(length_, w); }
  // w of any body point, from the sum of its distances to the foci.
  double Transmural(const Eigen::Vector3d& body) const;
  // The nu a fraction of the way along surface w's meridian arc from its
  // apex pole to the base plane.
  double NuAtArcFraction(double fraction, double w) const;
  // Volume (mm^3) inside surface w closed by the base plane, analytic.
  double ClosedVolume(double w) const;

 private:
  LvShapeSize size_;
  double length_, a_, d_, mu_mid_, dmu_;
};

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_SHAPE_H_
