#include "pfdm/fit/stages/top_slice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "Eigen/Geometry"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model_surface.h"

namespace pfdm {
namespace {

std::vector<Eigen::Vector3d> TopBand(const std::vector<Eigen::Vector3d>& points,
                                     const Eigen::Vector3d& axis) {
  double highest = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : points) {
    highest = std::max(highest, axis.dot(p));
  }
  std::vector<Eigen::Vector3d> band;
  for (const Eigen::Vector3d& p : points) {
    if (axis.dot(p) >= highest - kTopBandMm) band.push_back(p);
  }
  return band;
}

// The band's rms distance from the plane, and the share of its points
// farther than kOnSliceMm.
void MeasureFlatness(const std::vector<Eigen::Vector3d>& band,
                     const BasePlane& plane, TopSlice* top) {
  double sum = 0.0;
  int off = 0;
  for (const Eigen::Vector3d& p : band) {
    const double distance = plane.normal.dot(p - plane.point);
    sum += distance * distance;
    off += std::abs(distance) > kOnSliceMm;
  }
  top->rms_mm = std::sqrt(sum / band.size());
  top->off_slice_share = static_cast<double>(off) / band.size();
}

// The sectors about the axis that hold a point within kOnSliceMm of the
// plane, and those points' count; -1 when a point lies more than that
// above it.
int SectorsOnPlane(const std::vector<Eigen::Vector3d>& points,
                   const BasePlane& plane, const Eigen::Vector3d& on_axis,
                   const Eigen::Vector3d& axis, int* on_plane) {
  std::vector<Eigen::Vector3d> on;
  for (const Eigen::Vector3d& p : points) {
    const double above = plane.normal.dot(p - plane.point);
    if (above > kOnSliceMm) return -1;
    if (above >= -kOnSliceMm) on.push_back(p);
  }
  *on_plane = static_cast<int>(on.size());
  const Eigen::Vector3d x = axis.unitOrthogonal();
  const Eigen::Vector3d y = axis.cross(x);
  std::vector<bool> filled(kTopSectors, false);
  for (const Eigen::Vector3d& p : on) {
    const double angle = std::atan2(y.dot(p - on_axis), x.dot(p - on_axis));
    const int sector =
        static_cast<int>((angle + M_PI) / (2.0 * M_PI) * kTopSectors) %
        kTopSectors;
    filled[sector] = true;
  }
  return static_cast<int>(std::count(filled.begin(), filled.end(), true));
}

}  // namespace

int NeededTopSectors(int points_on_plane) {
  const double s = kTopSectors, n = points_on_plane;
  // Each sector's chance of staying empty, and a pair's.
  const double p1 = std::pow(1.0 - 1.0 / s, n), p2 = std::pow(1.0 - 2.0 / s, n);
  const double mean = s * (1.0 - p1);
  const double variance =
      std::max(0.0, s * p1 * (1.0 - p1) + s * (s - 1.0) * (p2 - p1 * p1));
  const int needed =
      static_cast<int>(std::floor(mean - 2.0 * std::sqrt(variance)));
  return std::clamp(needed, kMinSparseTopSectors, kMinTopSectors);
}

TopSlice FindTopSlice(const std::vector<Eigen::Vector3d>& points,
                      const Eigen::Vector3d& on_axis,
                      const Eigen::Vector3d& axis) {
  TopSlice top;
  const std::vector<Eigen::Vector3d> band = TopBand(points, axis);
  top.points = static_cast<int>(band.size());
  if (top.points < kMinTopPoints) return top;
  std::optional<BasePlane> plane = FitBasePlane(band);
  if (!plane) return top;
  if (plane->normal.dot(axis) < 0.0) plane->normal = -plane->normal;
  MeasureFlatness(band, *plane, &top);
  top.tilt_deg =
      std::acos(std::min(1.0, plane->normal.dot(axis))) * 180.0 / M_PI;
  int on_plane = 0;
  top.sectors = SectorsOnPlane(points, *plane, on_axis, axis, &on_plane);
  top.needed_sectors = NeededTopSectors(on_plane);
  top.found = top.rms_mm <= kTopPlaneRmsMm &&
              top.off_slice_share <= kMaxOffSliceShare &&
              top.tilt_deg <= kTopSliceTiltDeg &&
              top.sectors >= top.needed_sectors;
  return top;
}

double RimLift(bool top_is_slice, const Model& model) {
  return top_is_slice && model.config.Solid() ? LowestRimDrop(model) : 0.0;
}

bool TopIsSlice(const std::vector<Eigen::Vector3d>& points,
                const Model& model) {
  const Eigen::Vector3d center(model.state.center.data());
  return FindTopSlice(points, center, model.Rotation().col(2)).found;
}

}  // namespace pfdm
