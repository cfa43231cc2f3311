#include "pfdm/fit/stages/apex_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pfdm {
namespace {

// Points around the base rim whose mean height is the rim's.
constexpr int kRimPoints = 36;

}  // namespace

void MeasureApexCoverage(const std::vector<Eigen::Vector3d>& points,
                         SequenceFit* fit) {
  if (fit->frames.empty() || points.empty()) return;
  const Model model = fit->ModelAt(0);
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0);
  double rim = 0.0;
  for (int k = 0; k < kRimPoints; ++k) {
    const double v = -M_PI + 2.0 * M_PI * k / kRimPoints;
    rim += axis.dot(model.WorldPoint(model.config.u_max, v) - apex);
  }
  const double length = rim / kRimPoints;
  double lowest = std::numeric_limits<double>::infinity();
  double nearest = lowest;
  double highest = -lowest;
  int near_apex = 0;
  for (const Eigen::Vector3d& p : points) {
    lowest = std::min(lowest, axis.dot(p - apex) / length);
    highest = std::max(highest, axis.dot(p - apex) / length);
    const double distance = (p - apex).norm() / length;
    nearest = std::min(nearest, distance);
    near_apex += distance < kApexReach;
  }
  double lowest_u = std::numeric_limits<double>::infinity();
  for (const MaterialPoint& m : fit->frames[0].material) {
    lowest_u = std::min(lowest_u, m.u);
  }
  fit->apex_in_data =
      near_apex >= std::min(kApexPoints, static_cast<int>(points.size()));
  fit->lowest_data_height = lowest;
  fit->highest_data_height = highest;
  fit->apex_data_distance = nearest;
  fit->lowest_data_u =
      fit->frames[0].material.empty() ? model.config.u_min : lowest_u;
}

}  // namespace pfdm
