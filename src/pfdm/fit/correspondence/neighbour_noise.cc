#include "pfdm/fit/correspondence/neighbour_noise.h"

#include <numeric>

#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/util/point_cloud_tree.h"

namespace pfdm {

namespace {

// For each tag of `which` the difference of its residual and its nearest
// tag's, split along the normal of its layer (normals[k] for which[k]) and
// across it; `neighbours[k]` the index in `which` of the nearest tag.
struct NeighbourDifferences {
  std::vector<double> normal_squares, tangent_squares;
  std::vector<size_t> neighbours;
};
NeighbourDifferences DifferencesOfNeighbours(
    const std::vector<Eigen::Vector3d>& positions,
    const std::vector<Eigen::Vector3d>& residuals,
    const std::vector<Eigen::Vector3d>& normals,
    const std::vector<size_t>& which) {
  NeighbourDifferences differences;
  if (which.size() < 2) return differences;
  PointCloud cloud;
  for (size_t i : which) cloud.points.push_back(positions[i]);
  PointCloudTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  for (size_t k = 0; k < which.size(); ++k) {
    const size_t j = NearestOther(tree, cloud, k);
    Eigen::Vector3d d = residuals[which[k]] - residuals[which[j]];
    const double along = d.dot(normals[k]);
    d -= along * normals[k];
    differences.normal_squares.push_back(along * along);
    differences.tangent_squares.push_back(d.squaredNorm());
    differences.neighbours.push_back(j);
  }
  return differences;
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double value : values) sum += value;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

}  // namespace

double NeighbourTangentialNoiseMm(const Model& model,
                                  const std::vector<Eigen::Vector3d>& positions,
                                  const std::vector<Eigen::Vector3d>& residuals,
                                  const std::vector<MaterialPoint>& material,
                                  const std::vector<size_t>& which, bool robust,
                                  const std::vector<double>* stretch_squared) {
  if (which.size() < 2) return 0.0;
  std::vector<MaterialPoint> tag_material;
  for (size_t i : which) tag_material.push_back(material[i]);
  NeighbourDifferences differences = DifferencesOfNeighbours(
      positions, residuals, SurfaceNormals(model, tag_material), which);
  // Each tangential direction of a difference carries 4 sigma^2 where the
  // wall has not moved since frame 0; a stretched wall's tags carry more of
  // frame 0's noise, a contracted one's less: scaled to the unmoved wall's.
  if (stretch_squared != nullptr) {
    for (size_t k = 0; k < which.size(); ++k) {
      const double gain = 4.0 + (*stretch_squared)[k] +
                          (*stretch_squared)[differences.neighbours[k]];
      differences.tangent_squares[k] *= 8.0 / gain;
    }
  }
  return SigmaFromChiSquared2(&differences.tangent_squares, 4.0, robust);
}

double NeighbourNormalExcessMm2(const std::vector<Eigen::Vector3d>& positions,
                                const std::vector<Eigen::Vector3d>& residuals,
                                const std::vector<Eigen::Vector3d>& normals) {
  std::vector<size_t> every(positions.size());
  std::iota(every.begin(), every.end(), size_t{0});
  const NeighbourDifferences differences =
      DifferencesOfNeighbours(positions, residuals, normals, every);
  return Mean(differences.normal_squares) / 2.0 -
         Mean(differences.tangent_squares) / 4.0;
}

}  // namespace pfdm
