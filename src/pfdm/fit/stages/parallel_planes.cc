#include "pfdm/fit/stages/parallel_planes.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "Eigen/Dense"

namespace pfdm {
namespace {

constexpr size_t kMaxPoints = 2000;
// Of them, the directions are searched on this many.
constexpr size_t kSearchPoints = 500;
constexpr size_t kMinPoints = 30;
// Contour points sit in their image plane; tags at end-diastole within
// their noise (0.5 mm) of it.
constexpr double kTolerance = 1.0;
// Directions searched (2.6 degrees apart: over a 60 mm slice, heights then
// spread by at most 1.4 mm), the best of them tried, at least 10 degrees
// apart, and bins per direction at most.
constexpr int kDirections = 3000;
constexpr size_t kHypotheses = 6;
constexpr int kMaxBins = 4096;
constexpr double kSameDirection = 10.0 * 3.14159265358979323846 / 180.0;
constexpr int kMaxPlanes = 40;
constexpr double kMinPlaneShare = 0.02;
constexpr int kMinPlanePoints = 5;
// A plane's flanks (1-3 mm away on both sides, twice its width) against
// its slab: a cloud spread evenly along the normal has twice as many there.
constexpr double kMaxFlankRatio = 0.5;
constexpr double kMinFraction = 0.5;

// At most `most` of the points, evenly spread over their order.
std::vector<Eigen::Vector3d> Spread(const std::vector<Eigen::Vector3d>& points,
                                    size_t most) {
  if (points.size() <= most) return points;
  std::vector<Eigen::Vector3d> kept;
  for (size_t k = 0; k < most; ++k) {
    kept.push_back(points[k * points.size() / most]);
  }
  return kept;
}

// How concentrated the points' heights along `normal` are: the sum of the
// squared shares of bins kTolerance wide (the larger of two grids offset
// by half a bin): 1 / k for points on k planes normal to it, about
// kTolerance / extent for points spread along it.
double Concentration(const std::vector<Eigen::Vector3d>& points,
                     const Eigen::Vector3d& normal,
                     std::vector<double>* heights, std::vector<int>* bins) {
  heights->clear();
  for (const Eigen::Vector3d& p : points) heights->push_back(normal.dot(p));
  const auto [low, high] =
      std::minmax_element(heights->begin(), heights->end());
  const double bottom = *low;
  const double width = std::max(kTolerance, (*high - bottom) / kMaxBins);
  const size_t count = static_cast<size_t>((*high - bottom) / width) + 2;
  double best = 0.0;
  for (double offset : {0.0, 0.5}) {
    bins->assign(count, 0);
    for (double h : *heights) {
      ++(*bins)[static_cast<size_t>((h - bottom) / width + offset)];
    }
    double sum = 0.0;
    for (int count : *bins) sum += static_cast<double>(count) * count;
    best = std::max(best, sum);
  }
  return best / (static_cast<double>(points.size()) * points.size());
}

// The directions (unit normals over a hemisphere, a Fibonacci lattice) along
// which the points' heights are most concentrated, the best of each
// neighbourhood (kSameDirection), best first.  Points on parallel planes
// concentrate along their normal; a single plane holding many points (a
// long-axis contour) along its own, hence several.
std::vector<Eigen::Vector3d> ConcentratedDirections(
    const std::vector<Eigen::Vector3d>& points) {
  std::vector<std::pair<double, Eigen::Vector3d>> scored;
  std::vector<double> heights;
  std::vector<int> bins;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kDirections; ++k) {
    const double z = (k + 0.5) / kDirections;  // The upper hemisphere.
    const double r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d n(r * std::cos(golden * k), r * std::sin(golden * k),
                            z);
    scored.emplace_back(Concentration(points, n, &heights, &bins), n);
  }
  std::sort(scored.begin(), scored.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Eigen::Vector3d> directions;
  for (const auto& [score, n] : scored) {
    const bool near = std::any_of(
        directions.begin(), directions.end(), [&](const Eigen::Vector3d& d) {
          return std::abs(d.dot(n)) > std::cos(kSameDirection);
        });
    if (!near) directions.push_back(n);
    if (directions.size() == kHypotheses) break;
  }
  return directions;
}

int CountWithin(const std::vector<double>& sorted, double low, double high) {
  return static_cast<int>(std::lower_bound(sorted.begin(), sorted.end(), high) -
                          std::lower_bound(sorted.begin(), sorted.end(), low));
}

// The heights (along the normal) of the planes: slabs 2 mm wide, densest
// first, each much denser than its flanks.
std::vector<double> PlaneHeights(const std::vector<double>& sorted,
                                 std::vector<int>* counts) {
  const int n = static_cast<int>(sorted.size());
  const int min_count =
      std::max(kMinPlanePoints, static_cast<int>(kMinPlaneShare * n));
  std::vector<bool> taken(n, false);
  std::vector<double> heights;
  std::vector<int> free_before(n + 1, 0);
  while (static_cast<int>(heights.size()) <= kMaxPlanes) {
    for (int k = 0; k < n; ++k) free_before[k + 1] = free_before[k] + !taken[k];
    int best = -1, best_count = 0;
    for (int i = 0, j = 0; i < n; ++i) {  // Slabs [h_i, h_i + 2 tolerance).
      j = std::max(j, i);
      while (j < n && sorted[j] < sorted[i] + 2 * kTolerance) ++j;
      const int free = free_before[j] - free_before[i];
      if (free > best_count) best_count = free, best = i;
    }
    if (best < 0 || best_count < min_count) break;
    const double center = sorted[best] + kTolerance;
    const int slab =
        CountWithin(sorted, center - kTolerance, center + kTolerance);
    const int flanks =
        CountWithin(sorted, center - 3 * kTolerance, center + 3 * kTolerance) -
        slab;
    for (int k = best; k < n && sorted[k] < center + kTolerance; ++k) {
      taken[k] = true;
    }
    if (flanks > kMaxFlankRatio * slab) continue;
    heights.push_back(center);
    counts->push_back(best_count);
  }
  return heights;
}

struct Planes {
  ParallelPlanes planes;
  std::vector<double> heights;
};

// The planes normal to `normal`, if they pass (see the header).
std::optional<Planes> PlanesAlong(const std::vector<Eigen::Vector3d>& points,
                                  const Eigen::Vector3d& normal) {
  std::vector<double> sorted;
  for (const Eigen::Vector3d& p : points) sorted.push_back(normal.dot(p));
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> counts;
  std::vector<double> heights = PlaneHeights(sorted, &counts);
  int on_planes = 0;
  for (int count : counts) on_planes += count;
  const double fraction = static_cast<double>(on_planes) / points.size();
  if (heights.size() < 2 || static_cast<int>(heights.size()) > kMaxPlanes ||
      !(fraction > kMinFraction)) {
    return std::nullopt;
  }
  return Planes{{normal, static_cast<int>(heights.size()), fraction},
                std::move(heights)};
}

// The direction in which the planes' points vary least about their own
// plane's mean height.
Eigen::Vector3d Refined(const std::vector<Eigen::Vector3d>& points,
                        const Planes& found) {
  const Eigen::Vector3d& normal = found.planes.normal;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (double height : found.heights) {
    std::vector<Eigen::Vector3d> on;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
      if (std::abs(normal.dot(p) - height) < kTolerance) {
        on.push_back(p);
        mean += p;
      }
    }
    if (on.empty()) continue;
    mean /= static_cast<double>(on.size());
    for (const Eigen::Vector3d& p : on) {
      scatter += (p - mean) * (p - mean).transpose();
    }
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter)
      .eigenvectors()
      .col(0);
}

}  // namespace

std::optional<ParallelPlanes> FindParallelPlanes(
    const std::vector<Eigen::Vector3d>& all_points) {
  const std::vector<Eigen::Vector3d> points = Spread(all_points, kMaxPoints);
  if (points.size() < kMinPoints) return std::nullopt;
  std::optional<Planes> best;
  for (const Eigen::Vector3d& direction :
       ConcentratedDirections(Spread(points, kSearchPoints))) {
    std::optional<Planes> found = PlanesAlong(points, direction);
    if (!found) continue;
    // The lattice's direction, off by up to 1.3 degrees, refined.
    if (auto refined = PlanesAlong(points, Refined(points, *found))) {
      found = std::move(refined);
    }
    if (found && (!best || found->planes.fraction > best->planes.fraction)) {
      best = std::move(found);
    }
  }
  if (!best) return std::nullopt;
  return best->planes;
}

}  // namespace pfdm
