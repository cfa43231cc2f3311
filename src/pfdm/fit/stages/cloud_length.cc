#include "pfdm/fit/stages/cloud_length.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Eigen/Dense"

namespace pfdm {

double CloudLength::DegreesFrom(const Eigen::Vector3d& direction) const {
  const double cosine =
      std::min(1.0, std::abs(axis.dot(direction.normalized())));
  return std::acos(cosine) * 180.0 / M_PI;
}

bool CloudLength::Across(const Eigen::Vector3d& direction) const {
  return Elongated() && DegreesFrom(direction) > kAcrossDegrees;
}

CloudLength LengthOf(const std::vector<Eigen::Vector3d>& points) {
  CloudLength length;
  if (points.size() < 2) return length;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) {
    covariance += (p - mean) * (p - mean).transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascending: the largest spread last.
  const Eigen::Vector3d variance = solver.eigenvalues().cwiseMax(0.0);
  length.axis = solver.eigenvectors().col(2);
  length.ratio = variance[1] > 0.0 ? std::sqrt(variance[2] / variance[1])
                                   : std::numeric_limits<double>::infinity();
  return length;
}

}  // namespace pfdm
