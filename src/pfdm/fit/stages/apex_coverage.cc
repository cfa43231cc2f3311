#include "pfdm/fit/stages/apex_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pfdm {
namespace {

// Points around the base rim whose mean height is the rim's.
constexpr int kRimPoints = 36;

// The model's apex pole, its axis, and its length from the apex to the base
// rim's mean height.
struct ApexFrame {
  explicit ApexFrame(const Model& model)
      : axis(model.Rotation().col(2)),
        apex(model.WorldPoint(model.config.u_min, 0.0)) {
    double rim = 0.0;
    for (int k = 0; k < kRimPoints; ++k) {
      const double v = -M_PI + 2.0 * M_PI * k / kRimPoints;
      rim += axis.dot(model.WorldPoint(model.config.u_max, v) - apex);
    }
    length = rim / kRimPoints;
  }
  // Distance from the apex, in lengths.
  double Reach(const Eigen::Vector3d& p) const {
    return (p - apex).norm() / length;
  }
  Eigen::Vector3d axis, apex;
  double length = 0.0;
};

bool EnoughNearTheApex(int near_apex, size_t num_points) {
  return near_apex >= std::min(kApexPoints, static_cast<int>(num_points));
}

}  // namespace

bool ApexInData(const Model& model, const std::vector<Eigen::Vector3d>& points,
                double reach) {
  const ApexFrame frame(model);
  int near_apex = 0;
  for (const Eigen::Vector3d& p : points) {
    near_apex += frame.Reach(p) < reach;
  }
  return EnoughNearTheApex(near_apex, points.size());
}

void MeasureApexCoverage(const std::vector<Eigen::Vector3d>& points,
                         SequenceFit* fit) {
  if (fit->frames.empty() || points.empty()) return;
  const Model model = fit->ModelAt(0);
  const ApexFrame frame(model);
  double lowest = std::numeric_limits<double>::infinity();
  double nearest = lowest;
  double highest = -lowest;
  int near_apex = 0;
  for (const Eigen::Vector3d& p : points) {
    const double height = frame.axis.dot(p - frame.apex) / frame.length;
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
    const double distance = frame.Reach(p);
    nearest = std::min(nearest, distance);
    near_apex += distance < kApexReach;
  }
  double lowest_u = std::numeric_limits<double>::infinity();
  for (const MaterialPoint& m : fit->frames[0].material) {
    lowest_u = std::min(lowest_u, m.u);
  }
  fit->apex_in_data = EnoughNearTheApex(near_apex, points.size());
  fit->lowest_data_height = lowest;
  fit->highest_data_height = highest;
  fit->apex_data_distance = nearest;
  fit->lowest_data_u =
      fit->frames[0].material.empty() ? model.config.u_min : lowest_u;
}

}  // namespace pfdm
