#include "pfdm/fit/problem/directional_noise.h"

#include <algorithm>
#include <cmath>

#include "pfdm/fit/correspondence/neighbour_noise.h"
#include "pfdm/fit/residuals/robust_loss.h"

namespace pfdm {

DirectionalSigma DirectionalDataSigma(
    const std::vector<Eigen::Vector3d>& residuals,
    const std::vector<Eigen::Vector3d>& wall_normals, const std::string& loss,
    double loss_scale_mm, double normal_parameters, double tangent_parameters) {
  const std::vector<double> weights =
      LossWeights(loss, loss_scale_mm, residuals);
  double normal_sum = 0.0, tangent_sum = 0.0, count = 0.0;
  for (size_t i = 0; i < residuals.size(); ++i) {
    const double along = wall_normals[i].dot(residuals[i]);
    normal_sum += weights[i] * along * along;
    tangent_sum += weights[i] * (residuals[i].squaredNorm() - along * along);
    count += weights[i];
  }
  DirectionalSigma sigma;
  sigma.normal_mm =
      std::sqrt(normal_sum / std::max(1.0, count - normal_parameters));
  sigma.tangent_mm =
      std::sqrt(tangent_sum / std::max(1.0, 2.0 * count - tangent_parameters));
  return sigma;
}

Eigen::MatrixXd DirectionalCovariance(const NormalParts& parts, int n,
                                      double sigma_mm, double tangent_mm) {
  const Eigen::MatrixXd head = parts.pseudo_inverse.topRows(n);
  return sigma_mm * sigma_mm * parts.pseudo_inverse.topLeftCorner(n, n) +
         (tangent_mm * tangent_mm - sigma_mm * sigma_mm) * head *
             parts.data_normal * head.transpose();
}

void ScaleByDirectionalNoise(const NormalParts& parts,
                             const Eigen::MatrixXd& normal_data_normal,
                             const Model& model,
                             const std::vector<Eigen::Vector3d>& points,
                             const std::vector<MaterialPoint>& material,
                             const std::vector<Eigen::Vector3d>& wall_normals,
                             const std::string& loss, double loss_scale_mm,
                             bool depths_held, FrameCovariance* covariance) {
  const double normal_parameters =
      parts.pseudo_inverse.cwiseProduct(normal_data_normal).sum();
  const std::vector<Eigen::Vector3d> residuals =
      Residuals(model, points, material);
  const DirectionalSigma split = DirectionalDataSigma(
      residuals, wall_normals, loss, loss_scale_mm, normal_parameters,
      covariance->effective_parameters - normal_parameters);
  const int n = static_cast<int>(covariance->entries.size());
  covariance->covariance =
      DirectionalCovariance(parts, n, covariance->sigma_mm, split.tangent_mm);
  covariance->normal_sigma_mm = split.normal_mm;
  covariance->tangent_sigma_mm = split.tangent_mm;
  if (!depths_held) return;
  const double excess =
      NeighbourNormalExcessMm2(points, residuals, wall_normals);
  if (excess <= 0.0) return;
  const Eigen::MatrixXd head = parts.pseudo_inverse.topRows(n);
  covariance->depth_noise =
      excess * head * normal_data_normal * head.transpose();
  covariance->covariance += covariance->depth_noise;
}

}  // namespace pfdm
