#include "pfdm/fit/stages/initialization.h"

#include <algorithm>
#include <cmath>

#include "Eigen/Dense"
#include "ceres/rotation.h"
#include "glog/logging.h"

namespace pfdm {
namespace {

constexpr double kInitialA3 = 0.8;

double Median(std::vector<double> values) {
  CHECK(!values.empty());
  auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Mean distance from the axis of the points in the lowest and highest
// fifths along it.
std::pair<double, double> EndRadii(const std::vector<Eigen::Vector3d>& local) {
  std::vector<double> z;
  for (const auto& p : local) z.push_back(p.z());
  std::sort(z.begin(), z.end());
  const double low = z[z.size() / 5];
  const double high = z[z.size() * 4 / 5];
  double low_sum = 0, high_sum = 0;
  int low_count = 0, high_count = 0;
  for (const auto& p : local) {
    const double r = p.head<2>().norm();
    if (p.z() <= low) low_sum += r, ++low_count;
    if (p.z() >= high) high_sum += r, ++high_count;
  }
  return {low_sum / std::max(low_count, 1), high_sum / std::max(high_count, 1)};
}

}  // namespace

Model InitializeModel(const ModelConfig& config,
                      const std::vector<Eigen::Vector3d>& points,
                      const std::optional<AxisHint>& hint) {
  CHECK_GE(points.size(), 4u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= points.size();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);

  Eigen::Vector3d axis = hint ? (hint->base_center - hint->apex).normalized()
                              : Eigen::Vector3d(eigen.eigenvectors().col(2));
  // Across-axis principal direction: the covariance projected off the axis.
  const Eigen::Matrix3d off_axis =
      Eigen::Matrix3d::Identity() - axis * axis.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> across(off_axis * covariance *
                                                        off_axis);
  Eigen::Vector3d x_axis = across.eigenvectors().col(2);

  auto local_points = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& z) {
    const Eigen::Vector3d y = z.cross(x);
    std::vector<Eigen::Vector3d> local;
    for (const auto& p : points) {
      const Eigen::Vector3d d = p - mean;
      local.emplace_back(d.dot(x), d.dot(y), d.dot(z));
    }
    return local;
  };
  if (!hint) {
    const auto [low_radius, high_radius] = EndRadii(local_points(x_axis, axis));
    if (low_radius > high_radius) axis = -axis;
  }
  double third_moment = 0.0;
  for (const auto& p : points)
    third_moment += std::pow((p - mean).dot(x_axis), 3);
  if (third_moment < 0.0) x_axis = -x_axis;
  const Eigen::Vector3d y_axis = axis.cross(x_axis);

  std::vector<Eigen::Vector3d> local = local_points(x_axis, axis);
  double z_apex, z_base;
  if (hint) {
    z_apex = (hint->apex - mean).dot(axis);
    z_base = (hint->base_center - mean).dot(axis);
  } else {
    z_apex = z_base = local[0].z();
    for (const auto& p : local) {
      z_apex = std::min(z_apex, p.z());
      z_base = std::max(z_base, p.z());
    }
  }
  const double sin_min = std::sin(config.u_min);
  const double sin_max = std::sin(config.u_max);
  const double a0 = (z_base - z_apex) / (kInitialA3 * (sin_max - sin_min));
  // The u = 0 ring sits at the model origin.
  const double z_origin = z_apex - a0 * kInitialA3 * sin_min;

  std::vector<double> radius_x, radius_y;
  for (const auto& p : local) {
    const double s =
        std::clamp((p.z() - z_origin) / (a0 * kInitialA3), -1.0, 1.0);
    const double c = std::sqrt(1.0 - s * s);
    if (c < 0.5) continue;
    radius_x.push_back(p.x() * p.x() / (c * c));
    radius_y.push_back(p.y() * p.y() / (c * c));
  }
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = a0;
  values[kA3] = kInitialA3;
  values[kA1] = values[kA2] = 0.3;
  if (radius_x.size() >= 4) {
    // For points spread around an ellipse, mean x^2 = a^2 / 2.
    values[kA1] = std::clamp(std::sqrt(2.0 * Median(radius_x)) / a0, 0.02, 1.0);
    values[kA2] = std::clamp(std::sqrt(2.0 * Median(radius_y)) / a0, 0.02, 1.0);
  }

  Model model = Model::Uniform(config, values);
  Eigen::Matrix3d rotation;
  rotation << x_axis, y_axis, axis;
  const Eigen::Vector3d center = mean + z_origin * axis;
  for (int i = 0; i < 3; ++i) model.state.center[i] = center[i];
  ceres::RotationMatrixToQuaternion(rotation.data(),
                                    model.state.quaternion.data());
  return model;
}

}  // namespace pfdm
