#include "pfdm/fit/correspondence/surface_grid.h"

#include "pfdm/util/angles.h"

namespace pfdm {

SurfaceGrid::SurfaceGrid(const Model& model) {
  samples_.reserve(kGridU * kGridV);
  for (int i = 0; i < kGridU; ++i) {
    const double u =
        model.config.u_min +
        (model.config.u_max - model.config.u_min) * i / (kGridU - 1);
    for (int j = 0; j < kGridV; ++j) {
      samples_.push_back({u, -kPi + 2.0 * kPi * j / kGridV});
    }
  }
  // In batches (WorldPoints): 0.33 ms a grid, 0.53 one point at a time.
  cloud_.points = WorldPoints(model, samples_);
  tree_ = std::make_unique<PointCloudTree>(
      3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree_->buildIndex();
}

SurfaceGrid::Nearest SurfaceGrid::NearestTo(const Eigen::Vector3d& p) const {
  unsigned int nearest = 0;
  double distance_squared = 0.0;
  tree_->knnSearch(p.data(), 1, &nearest, &distance_squared);
  return {nearest, distance_squared};
}

}  // namespace pfdm
