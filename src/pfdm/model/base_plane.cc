#include "pfdm/model/base_plane.h"

#include <filesystem>

#include "Eigen/Eigenvalues"
#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

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
  // Points on a line have one large spread only: no normal is defined.
  if (eigen.eigenvalues()(1) < 1e-6 * eigen.eigenvalues()(2))
    return std::nullopt;
  return BasePlane{mean, eigen.eigenvectors().col(0),
                   static_cast<int>(points.size())};
}

std::vector<BasePlane> MitralValvePlanes(const std::string& gp_path) {
  const std::filesystem::path path(gp_path);
  if (!std::filesystem::is_directory(path) &&
      path.filename().string().rfind("GPFile", 0) != 0) {
    return {};
  }
  PointSequence valve;
  try {
    valve = ReadGpFiles(gp_path, {"MITRAL_VALVE"});
  } catch (const InputError&) {
    return {};  // Some frame has none: keep the flat lid for all.
  }
  std::vector<BasePlane> planes;
  for (const Frame& frame : valve.frames) {
    std::vector<Eigen::Vector3d> points;
    for (const DataPoint& p : frame.points) points.push_back(p.position);
    const std::optional<BasePlane> plane = FitBasePlane(points);
    if (!plane) return {};
    planes.push_back(*plane);
  }
  return planes;
}

}  // namespace pfdm
