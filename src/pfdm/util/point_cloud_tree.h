// A k-d tree over 3D points (nanoflann), for nearest-neighbour queries.
#ifndef PFDM_UTIL_POINT_CLOUD_TREE_H_
#define PFDM_UTIL_POINT_CLOUD_TREE_H_

#include <vector>

#include "Eigen/Core"
#include "nanoflann.hpp"

namespace pfdm {

// nanoflann's view of a vector of points.
struct PointCloud {
  std::vector<Eigen::Vector3d> points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][dim]; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const {
    return false;
  }
};

using PointCloudTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 3>;

// The point of `cloud` (the tree's) nearest its point i, other than i.
// The cloud has at least two points.
inline size_t NearestOther(const PointCloudTree& tree, const PointCloud& cloud,
                           size_t i) {
  unsigned int nearest[2];
  double distance_squared[2];
  tree.knnSearch(cloud.points[i].data(), 2, nearest, distance_squared);
  return nearest[0] == i ? nearest[1] : nearest[0];
}

}  // namespace pfdm

#endif  // PFDM_UTIL_POINT_CLOUD_TREE_H_
