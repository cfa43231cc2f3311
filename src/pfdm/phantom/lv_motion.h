// How the analytic LV phantom moves: the designed deformation of each
// material point (labelled by its end-diastolic body position) at systolic
// progress p, and the rigid motion of each scenario's frames.
//
// Deformation of X = (R cos phi, R sin phi, z), with h = z / base_z its
// ED height fraction (0 apex pole, 1 base) and w its transmural position:
//   z   -> (1 - LS p) z                       apex still, base descending;
//   R   -> (1 - c(h, w) p) R                  about the long axis;
//   phi -> phi + theta(h) p                   right-handed about +z;
//   c(h, w) = c_mid(h) - (endo + epi)/2 w + (endo - epi)/2 w^2,
//   c_mid(h) = c_apex + (c_base - c_apex) h, theta(h) linear from
//   apex_rotation_deg (h = 0) to base_rotation_deg (h = 1). Heights below 0
//   (the epicardial apex) extrapolate linearly.
// The three act on separate coordinates, so their order does not matter.
// The optional lesion scales c by 1 - lesion_loss g(h, lambda) in the mid
// third, lambda (longitude counted counter-clockwise about +z from -x, as
// report/wall_motion's regions count v) within 30 degrees of
// lesion_center_deg (default [60, 120] degrees: AHA segment 8, "mid 2").
// g is 1 inside and falls to 0 at the segment's edges over lesion_edge_h
// of height and lesion_edge_deg of longitude (smoothstep), so no other
// segment is touched.  Through the wall the lesion reaches from the
// endocardium (w = -1) to lesion_outer_w: 1 transmural, 0 the inner half
// (subendocardial, its edge smooth over lesion_edge_w about w = 0).
#ifndef PFDM_PHANTOM_LV_MOTION_H_
#define PFDM_PHANTOM_LV_MOTION_H_

#include <string>

#include "Eigen/Core"
#include "Eigen/Geometry"
#include "pfdm/phantom/lv_shape.h"

namespace pfdm {

// The myocardium (epi minus endo volume) keeps its volume within 1 % by
// end-systole, as a real one does within a few percent: the epicardium
// contracts 6.5 % at mid-height and the equatorial wall thickens from 10 to
// 14.6 mm (radial_epi_less = 0.06 once lost 26 % of it).
struct LvDeformation {
  double longitudinal_shortening = 0.17;
  double radial_apex = 0.24;        // c_mid at h = 0; 0.22 at mid-ventricle.
  double radial_base = 0.20;        // c_mid at h = 1.
  double radial_endo_extra = 0.08;  // c(h, -1) = c_mid + this.
  double radial_epi_less = 0.155;   // c(h, +1) = c_mid - this.
  double apex_rotation_deg = -10.0;
  double base_rotation_deg = 3.0;
  bool lesion = false;
  double lesion_loss = 0.7;  // Fraction of c lost inside the lesion.
  // Edges wide enough for the segment's truth to be the lesion's, not an
  // artefact of them: 5-degree edges stepped the radius by 15 % and
  // stretched the circumference, so the segment's mean Ecc was +18 %.
  double lesion_edge_h = 0.1;
  double lesion_edge_deg = 20.0;
  // The lesion spans 60 degrees of longitude about this one (90: segment
  // 8's middle); a test may move it to where a fit's sectors put segment 8.
  double lesion_center_deg = 90.0;
  double lesion_outer_w = 1.0;
  double lesion_edge_w = 0.4;
};

// How the contraction varies across the wall.  kDesigned: c(h, w) above, a
// quadratic in w.  kIncompressible: the epicardium contracts by
// c_epi(h) = c_mid(h) - radial_epi_less and every layer inside keeps the
// volume of a cylindrical shell about the axis, the wall's endocardium
// moving farthest: with R_w = R + w t / 2 (R, t the equatorial mid-wall
// radius and wall thickness, LvShapeSize) and lambda = 1 - LS p,
//   r_w^2 = r_epi^2 - (R_epi^2 - R_w^2) / lambda,  r_epi = (1 - c_epi p) R_epi,
// and the point at w moves radially by r_w / R_w.  Exact on the cylinder
// (lv_cylinder.h); on the prolate shell the equator's radii stand in for
// every height's (incompressible-ish away from the equator).  Defaults: 29 %
// endocardial contraction, 6.5 % epicardial, 43 % thickening at mid height.
enum class LvThickeningLaw { kDesigned, kIncompressible };
// "designed" or "incompressible"; false if unknown.
bool ParseLvThickeningLaw(const std::string& name, LvThickeningLaw* law);
std::string LvThickeningLawName(LvThickeningLaw law);

// The radii the incompressible law works on (mm): the equatorial mid-wall
// radius and wall thickness.
struct LvLawRadii {
  double midwall_mm = 27.0;
  double wall_mm = 10.0;
};

// r / R of a point at (h, w) at progress p under the law, without the
// lesion (1 - c(h, w) p for kDesigned).
double RadialFactor(const LvDeformation& design, LvThickeningLaw law,
                    const LvLawRadii& radii, double h, double w, double p);

// Designed values (fractions, degrees) at p = 1, without the lesion.
double DesignedRadialContraction(const LvDeformation& design, double h,
                                 double w);
double DesignedRotationDeg(const LvDeformation& design, double h);
// The lesion's weight g(h, lambda, w) in [0, 1], lambda in degrees (the
// endocardium's when w is left out).
double LesionWeight(const LvDeformation& design, double h, double lambda_deg,
                    double w = -1.0);

// A material point's labels, from its ED body position X.
struct LvMaterialPoint {
  double h = 0.0;       // X.z / base_z.
  double w = 0.0;       // Transmural position.
  double radius = 0.0;  // From the long axis.
  double phi = 0.0;     // atan2(X.y, X.x).
  double z = 0.0;
};
LvMaterialPoint MaterialPointAt(const LvShape& shape,
                                const Eigen::Vector3d& ed_body);

// Body position at progress p of a material point.
Eigen::Vector3d DeformedBodyPoint(
    const LvDeformation& design, const LvMaterialPoint& point, double p,
    LvThickeningLaw law = LvThickeningLaw::kDesigned,
    const LvLawRadii& radii = LvLawRadii());

enum class LvKinematics {
  kSystole,       // p 0 -> 1 linearly over the frames, with breathing.
  kCycle,         // p = sin^2(pi s): 0 -> 1 -> 0, breathing back to 0.
  kRigidAxial,    // 8 mm along the long axis by the last frame.
  kRigidLateral,  // 5 mm across it.
  kRigidTilt,     // 8 degrees about an axis across it through the centre.
  kRigidSpin,     // 10 degrees about the long axis.
  kStatic,
};
// "systole", "cycle", "rigid-axial", ..., "static"; false if unknown.
bool ParseLvKinematics(const std::string& name, LvKinematics* kinematics);
std::string LvKinematicsName(LvKinematics kinematics);
int DefaultFrameCount(LvKinematics kinematics);  // 9 for cycle, else 5.

// A rigid motion in body terms, applied after the deformation: tilt about
// kTiltAxis and spin about +z, both about the LV centre (0, 0, base_z / 2)
// on the long axis, then a shift along +z and along kLateral.
struct LvRigidMotion {
  double axial_shift_mm = 0.0;
  double lateral_shift_mm = 0.0;
  double tilt_deg = 0.0;
  double spin_deg = 0.0;
};
inline const Eigen::Vector3d kLvLateral{0.819152044288992, 0.573576436351046,
                                        0.0};  // 35 degrees from +x.
inline const Eigen::Vector3d kLvTiltAxis{-0.573576436351046, 0.819152044288992,
                                         0.0};  // 125.

struct LvFrameMotion {
  double progress = 0.0;  // p
  LvRigidMotion rigid;
};
// Frame t of num_frames: p and the rigid motion (breathing when asked for
// systole and cycle: 4 sin^2(pi f) mm axial, 2 sin(pi f) mm lateral and
// 2 sin^2(pi f) degrees of tilt, f = s / 2 in systole and s in the cycle,
// s = t / (num_frames - 1)).
LvFrameMotion ScenarioMotion(LvKinematics kinematics, int t, int num_frames,
                             bool breathing);

// Body (moved) from body (ED), and the fixed pose of the body in the world:
// 50 degrees about an oblique axis, the apex at (20, -35, 60) mm.
Eigen::Isometry3d RigidBodyMotion(const LvShape& shape,
                                  const LvRigidMotion& motion);
Eigen::Isometry3d LvWorldPose();

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_MOTION_H_
