#include "pfdm/fit/stages/tracked_ids.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pfdm/util/error.h"
#include "pfdm/util/median.h"
#include "pfdm/util/point_cloud_tree.h"
#include "pfdm/util/stride.h"

namespace pfdm {
namespace {

// At most this many of the frame before's points for the nearest-neighbour
// distances: fewer points only lengthen them, which makes a refusal less
// likely, and a million-point frame costs a tree of 20,000.
constexpr size_t kNearestSample = 20000;

// Every stride-th point, stride chosen to keep at most `most`.
std::vector<const DataPoint*> Sample(const Frame& frame, size_t most) {
  const size_t n = frame.points.size();
  const size_t stride = StrideForAtMost(n, most);
  std::vector<const DataPoint*> sample;
  for (size_t i = 0; i < n; i += stride) sample.push_back(&frame.points[i]);
  return sample;
}

double RadiusMm(const Frame& frame) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const DataPoint& p : frame.points) centroid += p.position;
  centroid /= static_cast<double>(frame.points.size());
  double sum = 0.0;
  for (const DataPoint& p : frame.points) {
    sum += (p.position - centroid).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(frame.points.size()));
}

// Median distance from each point to its nearest neighbour in the cloud.
double MedianNearestMm(const std::vector<Eigen::Vector3d>& points,
                       const Frame& cloud) {
  PointCloud sample;
  for (const DataPoint* p : Sample(cloud, kNearestSample)) {
    sample.points.push_back(p->position);
  }
  PointCloudTree tree(3, sample, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  std::vector<double> distances;
  for (const Eigen::Vector3d& x : points) {
    unsigned int nearest = 0;
    double distance_squared = 0.0;
    tree.knnSearch(x.data(), 1, &nearest, &distance_squared);
    distances.push_back(std::sqrt(distance_squared));
  }
  return Median(std::move(distances));
}

}  // namespace

IdMotion MeasureIdMotion(const Frame& before, const Frame& after,
                         bool nearest_if_needed) {
  // The sample's ids first, then one pass over `before`: a million-point
  // frame needs no map of all its ids.
  std::unordered_map<std::int64_t, Eigen::Vector3d> sampled;
  for (const DataPoint* p : Sample(after, kIdSample)) {
    sampled.emplace(p->id, p->position);
  }
  std::vector<Eigen::Vector3d> moved;
  std::vector<double> by_id;
  for (const DataPoint& p : before.points) {
    const auto found = sampled.find(p.id);
    if (found == sampled.end()) continue;
    by_id.push_back((found->second - p.position).norm());
    moved.push_back(found->second);
  }
  IdMotion motion;
  motion.shared = static_cast<int>(by_id.size());
  if (by_id.empty()) return motion;
  motion.by_id_mm = Median(std::move(by_id));
  motion.radius_mm = RadiusMm(before);
  if (!nearest_if_needed || MayBeScrambled(motion)) {
    motion.nearest_mm = MedianNearestMm(moved, before);
  }
  return motion;
}

bool MayBeScrambled(const IdMotion& motion) {
  return motion.shared >= 10 && motion.by_id_mm > 0.5 * motion.radius_mm;
}

bool IdsScrambled(const IdMotion& motion) {
  return MayBeScrambled(motion) && motion.by_id_mm > 4.0 * motion.nearest_mm;
}

void CheckIdsFollowPoints(const PointSequence& sequence,
                          const std::function<void()>& between) {
  for (size_t t = 1; t < sequence.frames.size(); ++t) {
    if (between) between();
    const Frame& before = sequence.frames[t - 1];
    const Frame& after = sequence.frames[t];
    // The nearest points' tree only where the ids moved far: a 20,000-tag
    // job built four of them (25 ms) to say what the motion already had.
    const IdMotion motion =
        MeasureIdMotion(before, after, /*nearest_if_needed=*/true);
    if (!IdsScrambled(motion)) continue;
    char numbers[200];
    std::snprintf(numbers, sizeof(numbers),
                  "the median point moved %.1f mm by its id but %.1f mm to "
                  "the nearest point, in data of radius %.1f mm",
                  motion.by_id_mm, motion.nearest_mm, motion.radius_mm);
    throw InputError(
        sequence.source + ": frame " + std::to_string(after.index) +
        ": the point ids do not follow the points of frame " +
        std::to_string(before.index) + " (scrambled?): " + numbers);
  }
}

}  // namespace pfdm
