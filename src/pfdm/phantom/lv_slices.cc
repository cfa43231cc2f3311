#include "pfdm/phantom/lv_slices.h"

#include <cmath>

namespace pfdm {
namespace {

// Bisection steps: nu's bracket (at most pi) shrinks to ~1e-15 rad.
constexpr int kBisections = 52;

// As LvWorldPoint (lv_phantom.h) moves a tag.
Eigen::Isometry3d WorldFromBody(const LvShape& shape,
                                const LvFrameMotion& motion) {
  return LvWorldPose() * RigidBodyMotion(shape, motion.rigid);
}

Eigen::Vector3d MovedPoint(const LvShape& shape,
                           const LvDeformation& deformation,
                           const LvFrameMotion& motion,
                           const Eigen::Isometry3d& world_from_body, double nu,
                           double phi, double w) {
  return world_from_body *
         DeformedBodyPoint(deformation,
                           MaterialPointAt(shape, shape.Position(nu, phi, w)),
                           motion.progress);
}

// Where moved(s), s in [low, high], crosses `plane`, by bisection; nullopt
// when its ends lie on the same side.
template <typename Moved>
std::optional<Eigen::Vector3d> PlaneCrossing(const Moved& moved,
                                             const LvImagePlane& plane,
                                             double low, double high) {
  auto side = [&](double s) {
    return plane.normal.dot(moved(s)) - plane.offset;
  };
  const double at_low = side(low);
  if (!(at_low * side(high) <= 0.0)) return std::nullopt;
  for (int i = 0; i < kBisections; ++i) {
    const double middle = 0.5 * (low + high);
    (side(middle) * at_low > 0.0 ? low : high) = middle;
  }
  return moved(0.5 * (low + high));
}

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
  const Eigen::Isometry3d world_from_body = WorldFromBody(shape, motion);
  // The meridian rises from the apex pole to the base: heights along the
  // normal grow with nu (the deformation keeps the order of heights, the
  // rigid motions tilt by degrees).
  return PlaneCrossing(
      [&](double nu) {
        return MovedPoint(shape, deformation, motion, world_from_body, nu, phi,
                          w);
      },
      plane, 0.0, shape.BaseNu(w));
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
  const Eigen::Isometry3d world_from_body = WorldFromBody(shape, motion);
  return PlaneCrossing(
      [&](double phi) {
        return MovedPoint(shape, deformation, motion, world_from_body, nu, phi,
                          w);
      },
      plane, phi0 - kLongAxisBracket, phi0 + kLongAxisBracket);
}

}  // namespace pfdm
