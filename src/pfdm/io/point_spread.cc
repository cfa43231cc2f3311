#include "pfdm/io/point_spread.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

Eigen::Vector3d MedianOf(const std::vector<DataPoint>& points) {
  Eigen::Vector3d median;
  std::vector<double> values(points.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t i = 0; i < points.size(); ++i) {
      values[i] = points[i].position[axis];
    }
    const auto middle = values.begin() + values.size() / 2;
    std::nth_element(values.begin(), middle, values.end());
    median[axis] = *middle;
  }
  return median;
}

}  // namespace

void CheckPointsLieTogether(const std::string& path, int frame,
                            const std::vector<DataPoint>& points,
                            const std::vector<unsigned>& lines) {
  if (points.empty()) return;
  const Eigen::Vector3d centre = MedianOf(points);
  size_t first = points.size();
  for (size_t i = 0; i < points.size(); ++i) {
    if ((points[i].position - centre).norm() > kMaxHeartRadiusMm &&
        (first == points.size() || lines[i] < lines[first])) {
      first = i;
    }
  }
  if (first == points.size()) return;
  char what[160];
  std::snprintf(what, sizeof(what),
                ": frame %d: the point lies %.0f mm from the centre of the "
                "frame's points, beyond any heart (%.0f mm)",
                frame, (points[first].position - centre).norm(),
                kMaxHeartRadiusMm);
  throw InputError(path + ":" + std::to_string(lines[first]) + what);
}

}  // namespace pfdm
