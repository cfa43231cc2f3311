// Where closest-point searches start: the model's mid-wall sampled on a
// (u, v) grid, with a k-d tree of the samples' world points.
#ifndef PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_
#define PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_

#include <memory>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_cloud_tree.h"

namespace pfdm {

// Built of one model's state, for every search on that state: a round of
// a solid searched the mid-wall and then the walls, and built the same tree
// twice (of a 443-point biv-me frame's search, the grid's world points and
// tree were most of the cost).  Immutable once built: threads share it.
class SurfaceGrid {
 public:
  static constexpr int kGridU = 48;
  static constexpr int kGridV = 72;

  explicit SurfaceGrid(const Model& model);
  SurfaceGrid(const SurfaceGrid&) = delete;
  SurfaceGrid& operator=(const SurfaceGrid&) = delete;

  // The sample nearest p and its squared distance.
  struct Nearest {
    size_t index;
    double distance_squared;
  };
  Nearest NearestTo(const Eigen::Vector3d& p) const;
  const MaterialPoint& Sample(size_t index) const { return samples_[index]; }

 private:
  std::vector<MaterialPoint> samples_;  // Row by row along u.
  PointCloud cloud_;
  std::unique_ptr<PointCloudTree> tree_;  // Refers to cloud_.
};

// ClosestMaterialPoints with its searches started from `grid`, which must
// have been built of this model.
std::vector<MaterialPoint> ClosestMaterialPointsFrom(
    const SurfaceGrid& grid, const Model& model,
    const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options = {},
    std::vector<Eigen::Vector3d>* model_points = nullptr,
    std::vector<Eigen::Vector3d>* normals = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_
