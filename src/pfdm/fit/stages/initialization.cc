#include "pfdm/fit/stages/initialization.h"

#include <algorithm>
#include <cmath>

#include "Eigen/Dense"
#include "ceres/rotation.h"
#include "glog/logging.h"
#include "pfdm/util/median.h"

namespace pfdm {
namespace {

constexpr double kInitialA3 = 0.8;
// ApexHeight: an apex this far below the lowest point, as a fraction of
// the length from the apex to the highest point, counts as beyond the data
// (a short-axis stack's lowest slice may lie 5 % of it above the apex);
// the extrapolation goes at most this many times the points' extent.
constexpr double kMinExtrapolation = 0.1;
constexpr double kMaxExtrapolation = 1.0;

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

// Where the points' radius profile closes below them: r^2 least-squares
// quadratic in z (exact for a spheroid), its lower root when the profile
// closes (concave) and the root lies more than kMinExtrapolation of the
// length below the lowest point, at most kMaxExtrapolation of the points'
// extent below it; else the lowest point.  Data without their apex (a
// mid-ventricular segment) so start with the cup closing where the shape
// says, not at the lowest ring, from which frame 0's rounds drifted
// without settling (its closest points moving by 9-11 mm in the tenth).
double ApexHeight(const std::vector<Eigen::Vector3d>& local, double z_low,
                  double z_high) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  const double scale = std::max(z_high - z_low, 1e-9);
  for (const auto& p : local) {
    const double t = (p.z() - z_low) / scale;  // 0 at the lowest point.
    const Eigen::Vector3d basis(1.0, t, t * t);
    normal += basis * basis.transpose();
    right += basis * p.head<2>().squaredNorm();
  }
  const Eigen::Vector3d q = normal.ldlt().solve(right);  // q0 + q1 t + q2 t^2
  const double discriminant = q[1] * q[1] - 4.0 * q[2] * q[0];
  if (!(q[2] < 0.0) || !(q[0] > 0.0) || !(discriminant > 0.0)) return z_low;
  // The root below t = 0 (q0 > 0 and q2 < 0: one on each side).
  const double root = (-q[1] + std::sqrt(discriminant)) / (2.0 * q[2]);
  const double below = -root;  // Of the extent, both roots' t scaled alike.
  if (!(below > kMinExtrapolation / (1.0 - kMinExtrapolation))) return z_low;
  return z_low - std::min(below, kMaxExtrapolation) * scale;
}

// The functions' values spanning [z_apex, z_base] (local heights) with a3
// = kInitialA3, a1 and a2 from the points' spread across the axis; *z_origin
// gets the height of the u = 0 ring, the model's origin.
FunctionValues InitialValues(const ModelConfig& config,
                             const std::vector<Eigen::Vector3d>& local,
                             double z_apex, double z_base, double* z_origin) {
  const double sin_min = std::sin(config.u_min);
  const double sin_max = std::sin(config.u_max);
  const double a0 = (z_base - z_apex) / (kInitialA3 * (sin_max - sin_min));
  *z_origin = z_apex - a0 * kInitialA3 * sin_min;
  std::vector<double> radius_x, radius_y;
  for (const auto& p : local) {
    const double s =
        std::clamp((p.z() - *z_origin) / (a0 * kInitialA3), -1.0, 1.0);
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
  return values;
}

// The model along `axis` (apex to base), its extent along it the hint's or
// the points'; `orient` first points the axis from the narrower end to the
// wider one.
Model Build(const ModelConfig& config,
            const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d axis,
            bool orient, const std::optional<AxisHint>& hint) {
  CHECK_GE(points.size(), 4u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= points.size();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
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
  if (orient) {
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
    z_apex = ApexHeight(local, z_apex, z_base);
  }
  double z_origin = 0.0;
  const FunctionValues values =
      InitialValues(config, local, z_apex, z_base, &z_origin);
  Model model = Model::Uniform(config, values);
  Eigen::Matrix3d rotation;
  rotation << x_axis, y_axis, axis;
  const Eigen::Vector3d center = mean + z_origin * axis;
  for (int i = 0; i < 3; ++i) model.state.center[i] = center[i];
  ceres::RotationMatrixToQuaternion(rotation.data(),
                                    model.state.quaternion.data());
  return model;
}

}  // namespace

Model InitializeModel(const ModelConfig& config,
                      const std::vector<Eigen::Vector3d>& points,
                      const std::optional<AxisHint>& hint) {
  if (hint) {
    return Build(config, points, (hint->base_center - hint->apex).normalized(),
                 false, hint);
  }
  return InitializeModelAlong(config, points, PrincipalAxes(points).col(2));
}

Model InitializeModelAlong(const ModelConfig& config,
                           const std::vector<Eigen::Vector3d>& points,
                           const Eigen::Vector3d& direction) {
  return Build(config, points, direction, true, std::nullopt);
}

Eigen::Matrix3d PrincipalAxes(const std::vector<Eigen::Vector3d>& points) {
  CHECK(!points.empty());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= points.size();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance)
      .eigenvectors();
}

}  // namespace pfdm
