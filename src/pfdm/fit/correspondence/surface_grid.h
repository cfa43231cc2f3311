// Where closest-point searches start: the model's mid-wall sampled on a
// (u, v) grid, with a k-d tree of the samples' world points.
#ifndef PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_
#define PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_

#include <memory>
#include <optional>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_cloud_tree.h"

namespace pfdm {

// Built of one model's state, for every search on that state: a round of
// a solid searched the mid-wall and then the walls, and built the same tree
// twice (of a 443-point biv-me frame's search, the grid's world points and
// tree were most of the cost).  Immutable between Follow calls: threads
// share it.
class SurfaceGrid {
 public:
  static constexpr int kGridU = 48;
  static constexpr int kGridV = 72;
  // Follow keeps the tree while no sample has moved farther than this from
  // where the tree holds it (the grid's spacing is 2-4 mm on an LV): a
  // frame's correspondence rounds then share one tree.
  static constexpr double kRebuildMm = 2.0;

  // Empty: the first Follow builds it.
  SurfaceGrid() = default;
  explicit SurfaceGrid(const Model& model);
  SurfaceGrid(const SurfaceGrid&) = delete;
  SurfaceGrid& operator=(const SurfaceGrid&) = delete;

  // The grid on `model`, whose state may have moved since the grid was
  // built: the samples' world points are evaluated afresh, the tree is
  // rebuilt only past kRebuildMm.  NearestTo's answers are those of a grid
  // built of `model` (up to ties).
  void Follow(const Model& model);

  // The sample nearest p and its squared distance.
  struct Nearest {
    size_t index;
    double distance_squared;
  };
  Nearest NearestTo(const Eigen::Vector3d& p) const;
  // The same if that sample is nearer than sqrt(squared_bound), else none:
  // a search with a hint needs the grid only where the grid beats the hint,
  // and the bound lets the tree prune nearly all of its cells.
  std::optional<Nearest> NearestWithin(const Eigen::Vector3d& p,
                                       double squared_bound) const;
  const MaterialPoint& Sample(size_t index) const { return samples_[index]; }
  // How many times the tree was built (a test's and a benchmark's count).
  int builds() const { return builds_; }

 private:
  void MakeSamples(const ModelConfig& config);
  void BuildTree();

  std::vector<MaterialPoint> samples_;  // Row by row along u.
  double u_min_ = 0.0, u_max_ = 0.0;    // Of the samples.
  // The samples' world points now, and where the tree was built of them,
  // at most drift_ (mm) apart.
  std::vector<Eigen::Vector3d> points_;
  PointCloud tree_cloud_;
  double drift_ = 0.0;
  std::unique_ptr<PointCloudTree> tree_;  // Refers to tree_cloud_.
  int builds_ = 0;
};

// ClosestMaterialPoints with its searches started from `grid`, which must
// have been built of (or have followed) this model.
std::vector<MaterialPoint> ClosestMaterialPointsFrom(
    const SurfaceGrid& grid, const Model& model,
    const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options = {},
    std::vector<Eigen::Vector3d>* model_points = nullptr,
    std::vector<Eigen::Vector3d>* normals = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_SURFACE_GRID_H_
