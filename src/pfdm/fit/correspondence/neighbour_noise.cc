#include "pfdm/fit/correspondence/neighbour_noise.h"

#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/util/point_cloud_tree.h"

namespace pfdm {

double NeighbourTangentialNoiseMm(const Model& model,
                                  const std::vector<Eigen::Vector3d>& positions,
                                  const std::vector<Eigen::Vector3d>& residuals,
                                  const std::vector<MaterialPoint>& material,
                                  const std::vector<size_t>& which,
                                  bool robust) {
  if (which.size() < 2) return 0.0;
  PointCloud cloud;
  std::vector<MaterialPoint> tag_material;
  for (size_t i : which) {
    cloud.points.push_back(positions[i]);
    tag_material.push_back(material[i]);
  }
  PointCloudTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, tag_material);
  std::vector<double> squares;
  squares.reserve(which.size());
  for (size_t k = 0; k < which.size(); ++k) {
    const size_t j = NearestOther(tree, cloud, k);
    Eigen::Vector3d d = residuals[which[k]] - residuals[which[j]];
    d -= d.dot(normals[k]) * normals[k];
    squares.push_back(d.squaredNorm());
  }
  // Each tangential direction of a difference carries 4 sigma^2.
  return SigmaFromChiSquared2(&squares, 4.0, robust);
}

}  // namespace pfdm
