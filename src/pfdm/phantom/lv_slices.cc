#include "pfdm/phantom/lv_slices.h"

#include <cmath>

namespace pfdm {
namespace {

// Bisection steps: nu's bracket (at most pi) shrinks to ~1e-15 rad.
constexpr int kBisections = 52;

}  // namespace

LvImagePlane ShortAxisPlane(const Eigen::Isometry3d& world_from_body,
                            double z) {
  LvImagePlane plane;
  plane.normal = world_from_body.linear() * Eigen::Vector3d::UnitZ();
  plane.offset = plane.normal.dot(world_from_body * Eigen::Vector3d(0, 0, z));
  return plane;
}

std::optional<Eigen::Vector3d> SliceCut(const LvShape& shape,
                                        const LvDeformation& deformation,
                                        const LvFrameMotion& motion,
                                        const LvImagePlane& plane, double phi,
                                        double w) {
  // As LvWorldPoint (lv_phantom.h) moves a tag.
  const Eigen::Isometry3d world_from_body =
      LvWorldPose() * RigidBodyMotion(shape, motion.rigid);
  auto moved = [&](double nu) -> Eigen::Vector3d {
    return world_from_body *
           DeformedBodyPoint(deformation,
                             MaterialPointAt(shape, shape.Position(nu, phi, w)),
                             motion.progress);
  };
  // The meridian rises from the apex pole to the base: heights along the
  // normal grow with nu (the deformation keeps the order of heights, the
  // rigid motions tilt by degrees).
  auto above = [&](double nu) {
    return plane.normal.dot(moved(nu)) - plane.offset;
  };
  double low = 0.0, high = shape.BaseNu(w);
  if (above(low) > 0.0 || above(high) < 0.0) return std::nullopt;
  for (int i = 0; i < kBisections; ++i) {
    const double middle = 0.5 * (low + high);
    (above(middle) < 0.0 ? low : high) = middle;
  }
  return moved(0.5 * (low + high));
}

LvImagePlane LongAxisPlane(const Eigen::Isometry3d& world_from_body,
                           double angle) {
  LvImagePlane plane;
  plane.normal = world_from_body.linear() *
                 Eigen::Vector3d(-std::sin(angle), std::cos(angle), 0.0);
  plane.offset = plane.normal.dot(world_from_body * Eigen::Vector3d::Zero());
  return plane;
}

std::optional<Eigen::Vector3d> LongAxisCut(const LvShape& shape,
                                           const LvDeformation& deformation,
                                           const LvFrameMotion& motion,
                                           const LvImagePlane& plane, double nu,
                                           double phi0, double w) {
  const Eigen::Isometry3d world_from_body =
      LvWorldPose() * RigidBodyMotion(shape, motion.rigid);
  auto moved = [&](double phi) -> Eigen::Vector3d {
    return world_from_body *
           DeformedBodyPoint(deformation,
                             MaterialPointAt(shape, shape.Position(nu, phi, w)),
                             motion.progress);
  };
  auto side = [&](double phi) {
    return plane.normal.dot(moved(phi)) - plane.offset;
  };
  double low = phi0 - kLongAxisBracket, high = phi0 + kLongAxisBracket;
  const double at_low = side(low);
  if (!(at_low * side(high) < 0.0)) return std::nullopt;
  for (int i = 0; i < kBisections; ++i) {
    const double middle = 0.5 * (low + high);
    (side(middle) * at_low > 0.0 ? low : high) = middle;
  }
  return moved(0.5 * (low + high));
}

}  // namespace pfdm
