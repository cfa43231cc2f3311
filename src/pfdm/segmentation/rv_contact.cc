#include "pfdm/segmentation/rv_contact.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pfdm/util/angles.h"

namespace pfdm {

namespace {

std::vector<Eigen::Vector2d> ContactPoints(const SliceMask& myocardium,
                                           const SliceMask& rv) {
  std::vector<Eigen::Vector2d> points;
  const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
  for (int j = 0; j < myocardium.ny; ++j) {
    for (int i = 0; i < myocardium.nx; ++i) {
      if (!myocardium.At(i, j)) continue;
      for (int n = 0; n < 4; ++n) {
        if (rv.At(i + di[n], j + dj[n])) {
          points.emplace_back(i + 0.5 * di[n], j + 0.5 * dj[n]);
        }
      }
    }
  }
  return points;
}

}  // namespace

std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> RvContactEnds(
    const SliceMask& myocardium, const SliceMask& rv,
    const Eigen::Vector2d& centre, double spacing_i, double spacing_j) {
  const std::vector<Eigen::Vector2d> points = ContactPoints(myocardium, rv);
  if (points.size() < 3) return std::nullopt;
  std::vector<std::pair<double, int>> angles;
  for (size_t n = 0; n < points.size(); ++n) {
    const Eigen::Vector2d d = points[n] - centre;
    angles.emplace_back(std::atan2(d.y() * spacing_j, d.x() * spacing_i),
                        static_cast<int>(n));
  }
  std::sort(angles.begin(), angles.end());
  // The largest gap, from angles[last] to angles[first] (+2 pi) included.
  size_t gap_end = 0;
  double gap = angles.front().first + 2.0 * kPi - angles.back().first;
  for (size_t n = 1; n < angles.size(); ++n) {
    const double g = angles[n].first - angles[n - 1].first;
    if (g > gap) {
      gap = g;
      gap_end = n;
    }
  }
  if (2.0 * kPi - gap < 20.0 * kPi / 180.0) return std::nullopt;
  const size_t gap_start = (gap_end + angles.size() - 1) % angles.size();
  return std::make_pair(points[angles[gap_end].second],
                        points[angles[gap_start].second]);
}

}  // namespace pfdm
