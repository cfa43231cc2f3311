// Short-axis slices of the analytic LV phantom: contour points where fixed
// image planes cut the moving wall, as the cine contours of a short-axis
// stack without long-axis views.
//
// The planes are fixed in the world (the scanner's), normal to the ED long
// axis; the wall moves through them, so a plane cuts other material in
// every frame, and a basal plane the base has descended below cuts nothing.
#ifndef PFDM_PHANTOM_LV_SLICES_H_
#define PFDM_PHANTOM_LV_SLICES_H_

#include <optional>

#include "Eigen/Core"
#include "Eigen/Geometry"
#include "pfdm/phantom/lv_motion.h"
#include "pfdm/phantom/lv_shape.h"

namespace pfdm {

// A world plane {x : normal . x = offset}, normal of unit length.
struct LvImagePlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
};

// The plane normal to the body's +z at body height z, in the world of
// `world_from_body` (frame 0's, for fixed planes).
LvImagePlane ShortAxisPlane(const Eigen::Isometry3d& world_from_body, double z);

// Where the plane cuts surface w's meridian of ED longitude phi at frame
// `motion` (world, noise-free): the material point (nu, phi, w) whose moved
// position lies on the plane, nu by bisection between the surface's apex
// pole and its base.  nullopt when the meridian does not reach the plane.
std::optional<Eigen::Vector3d> SliceCut(const LvShape& shape,
                                        const LvDeformation& deformation,
                                        const LvFrameMotion& motion,
                                        const LvImagePlane& plane, double phi,
                                        double w);

// The plane containing the body's z axis at angle `angle` (radians) from
// its x axis, in the world of `world_from_body`.
LvImagePlane LongAxisPlane(const Eigen::Isometry3d& world_from_body,
                           double angle);

// Where a long-axis plane cuts surface w's ring of ED height parameter nu
// at frame `motion`: the material point (nu, phi, w), phi within
// kLongAxisBracket of `phi0` (the plane's longitude at ED, or the
// opposite side's), whose moved position lies on the plane.  nullopt when
// the ring does not cross the plane there.
inline constexpr double kLongAxisBracket = 0.6;  // rad: twist stays below.
std::optional<Eigen::Vector3d> LongAxisCut(const LvShape& shape,
                                           const LvDeformation& deformation,
                                           const LvFrameMotion& motion,
                                           const LvImagePlane& plane, double nu,
                                           double phi0, double w);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_SLICES_H_
