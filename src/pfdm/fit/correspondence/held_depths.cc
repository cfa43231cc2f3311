#include "pfdm/fit/correspondence/held_depths.h"

#include <algorithm>
#include <cmath>

#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Beyond this many s outside the wall a depth is taken as at it.
constexpr double kFarSds = 8.0;
// Searches on the tag's layer and steps of w along its normal: the step
// is exact where the layers are parallel, so a few reach the layer.
constexpr int kInversePasses = 3;

double NormalDensity(double x) {
  return std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi);
}

double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

}  // namespace

double ShrunkDepth(double w_obs, double s) {
  if (!(s > 0.0)) return std::clamp(w_obs, -1.0, 1.0);
  // Odd: computed for w_obs >= 0, where Phi(b) - Phi(a) has its mass in b.
  const double sign = w_obs < 0.0 ? -1.0 : 1.0;
  const double x = std::min(std::abs(w_obs), 1.0 + kFarSds * s);
  const double a = (-1.0 - x) / s, b = (1.0 - x) / s;
  const double mass = NormalCdf(b) - NormalCdf(a);
  const double mean = x + s * (NormalDensity(a) - NormalDensity(b)) / mass;
  return sign * std::clamp(mean, -1.0, 1.0);
}

std::vector<MaterialPoint> HeldMaterialPoints(
    const Model& reference, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material, double sigma_mm) {
  std::vector<MaterialPoint> held = material;
  for (int pass = 0; pass < kInversePasses; ++pass) {
    CorrespondenceOptions options;
    for (const MaterialPoint& at : held) options.surfaces.push_back(at.w);
    options.hints = held;
    std::vector<Eigen::Vector3d> found, normals;
    held = ClosestMaterialPoints(reference, points, options, &found, &normals);
    for (size_t i = 0; i < held.size(); ++i) {
      const double h_fit = reference.FunctionsAt(held[i].u)[kH];
      held[i].w =
          options.surfaces[i] +
          (h_fit > 0.0 ? 2.0 * normals[i].dot(points[i] - found[i]) / h_fit
                       : 0.0);
    }
  }
  for (MaterialPoint& at : held) {
    const double h_fit = reference.FunctionsAt(at.u)[kH];
    const double h = DeconvolvedThickness(h_fit, sigma_mm);
    if (!(h > 0.0)) continue;
    at.w = ShrunkDepth(at.w * h_fit / h, 2.0 * sigma_mm / h);
  }
  return held;
}

}  // namespace pfdm
