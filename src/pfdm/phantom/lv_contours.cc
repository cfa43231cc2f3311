#include "pfdm/phantom/lv_contours.h"

#include <cmath>
#include <optional>
#include <utility>

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The surfaces contours are drawn on: the mid-wall, both walls, the
// endocardium or the epicardium.
std::vector<std::pair<double, WallLayer>> ContourSurfaces(
    const LvPhantomOptions& options) {
  switch (options.tags) {
    case LvTagLayer::kWall:
      return {{-1.0, WallLayer::kEndocardium}, {1.0, WallLayer::kEpicardium}};
    case LvTagLayer::kEndocardium:
      return {{-1.0, WallLayer::kEndocardium}};
    case LvTagLayer::kEpicardium:
      return {{1.0, WallLayer::kEpicardium}};
    case LvTagLayer::kMidwall:
      break;
  }
  return {{0.0, WallLayer::kAnywhere}};
}

// A contour point's drawing error: in the image plane only.  One
// distribution per frame's contours (it keeps half of each pair it draws).
Eigen::Vector3d InPlaneError(const LvImagePlane& plane, double noise_mm,
                             std::normal_distribution<double>* noise,
                             std::mt19937* noise_random) {
  Eigen::Vector3d error((*noise)(*noise_random), (*noise)(*noise_random),
                        (*noise)(*noise_random));
  error -= plane.normal * plane.normal.dot(error);
  return noise_mm * error;
}

// The next contour point, its id first_id on.
void AddPoint(const Eigen::Vector3d& x, WallLayer layer, std::int64_t first_id,
              std::vector<DataPoint>* points) {
  points->push_back(
      {first_id + static_cast<std::int64_t>(points->size()), x, layer});
}

}  // namespace

std::vector<DataPoint> LongAxisContours(
    const LvShape& shape, const LvPhantomOptions& options,
    const LvFrameMotion& motion, const Eigen::Isometry3d& ed_world_from_body,
    int per_contour, std::int64_t first_id, std::mt19937* placement,
    std::mt19937* noise_random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<DataPoint> points;
  for (int k = 0; k < options.num_long_axis_planes; ++k) {
    const double angle = kPi * k / options.num_long_axis_planes;
    const LvImagePlane plane = LongAxisPlane(ed_world_from_body, angle);
    for (const auto& [w, layer] : ContourSurfaces(options)) {
      for (int j = 0; j < per_contour; ++j) {
        const double nu = shape.BaseNu(w) * uniform(*placement);
        const std::optional<Eigen::Vector3d> cut =
            LongAxisCut(shape, options.deformation, motion, plane, nu,
                        angle + (j % 2) * kPi, w);
        const Eigen::Vector3d error =
            InPlaneError(plane, options.noise_mm, &noise, noise_random);
        if (cut) AddPoint(*cut + error, layer, first_id, &points);
      }
    }
  }
  return points;
}

std::vector<DataPoint> SliceContours(const LvShape& shape,
                                     const LvPhantomOptions& options,
                                     const LvFrameMotion& motion,
                                     const std::vector<LvImagePlane>& planes,
                                     int per_contour, std::int64_t first_id,
                                     std::mt19937* placement,
                                     std::mt19937* noise_random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  const auto surfaces = ContourSurfaces(options);
  std::vector<DataPoint> points;
  for (const LvImagePlane& plane : planes) {
    for (const auto& [w, layer] : surfaces) {
      for (int j = 0; j < per_contour; ++j) {
        const double phi = -kPi + 2.0 * kPi * uniform(*placement);
        const std::optional<Eigen::Vector3d> cut =
            SliceCut(shape, options.deformation, motion, plane, phi, w);
        const Eigen::Vector3d error =
            InPlaneError(plane, options.noise_mm, &noise, noise_random);
        if (cut) AddPoint(*cut + error, layer, first_id, &points);
      }
    }
  }
  return points;
}

}  // namespace pfdm
