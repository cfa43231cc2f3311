#include "pfdm/model/base_plane.h"

#include "Eigen/Eigenvalues"

namespace pfdm {

std::optional<BasePlane> FitBasePlane(
    const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 3) return std::nullopt;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  // Points on a line have one large spread only, points at one place none
  // (all eigenvalues 0 once passed the relative test): no normal is
  // defined.  The largest spread must reach a micrometre rms.
  const Eigen::Vector3d spread = eigen.eigenvalues();
  if (!(spread(2) >= 1e-6 * static_cast<double>(points.size())) ||
      spread(1) < 1e-6 * spread(2)) {
    return std::nullopt;
  }
  return BasePlane{mean, eigen.eigenvectors().col(0),
                   static_cast<int>(points.size())};
}

}  // namespace pfdm
