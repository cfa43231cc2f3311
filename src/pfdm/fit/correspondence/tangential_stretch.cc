#include "pfdm/fit/correspondence/tangential_stretch.h"

#include <cmath>

namespace pfdm {
namespace {

// Below this determinant of the reference's metric (mm^4 per rad^4) the
// tangents are taken as degenerate: at the pole dx/dv vanishes.
constexpr double kMinMetricDeterminant = 1e-8;
constexpr double kUnmoved = 2.0;

}  // namespace

std::vector<double> TangentialStretchSquared(
    const Model& reference, const Model& model,
    const std::vector<MaterialPoint>& material) {
  const std::vector<Eigen::Matrix<double, 3, 2>> from =
      SurfaceTangents(reference, material);
  const std::vector<Eigen::Matrix<double, 3, 2>> to =
      SurfaceTangents(model, material);
  std::vector<double> stretch(material.size(), kUnmoved);
  for (size_t i = 0; i < material.size(); ++i) {
    const Eigen::Matrix2d g_from = from[i].transpose() * from[i];
    if (!(g_from.determinant() > kMinMetricDeterminant)) continue;
    const double s = (g_from.inverse() * (to[i].transpose() * to[i])).trace();
    if (std::isfinite(s)) stretch[i] = s;
  }
  return stretch;
}

}  // namespace pfdm
