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

// The half-width a of the uniform the tags' depths fill, from their
// observed depths' mean square less the noise's (the variance of a uniform
// on [-a, a] is a^2 / 3), w_sum_squares and s_sum_squares their sums over
// n tags; 1 without noise.  Not below kMinHalfWidth.
constexpr double kMinHalfWidth = 0.5;
double PriorHalfWidth(double w_sum_squares, double s_sum_squares, int n,
                      double sigma_mm) {
  if (!(sigma_mm > 0.0) || n == 0) return 1.0;
  return std::sqrt(std::max(kMinHalfWidth * kMinHalfWidth,
                            3.0 * (w_sum_squares - s_sum_squares) / n));
}

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
  std::vector<double> w_obs(held.size(), 0.0), s(held.size(), 0.0);
  double ww = 0.0, ss = 0.0;
  int n = 0;
  for (size_t i = 0; i < held.size(); ++i) {
    const double h_fit = reference.FunctionsAt(held[i].u)[kH];
    const double h = DeconvolvedThickness(h_fit, sigma_mm);
    if (!(h > 0.0)) continue;
    w_obs[i] = held[i].w * h_fit / h;
    s[i] = 2.0 * sigma_mm / h;
    ww += w_obs[i] * w_obs[i];
    ss += s[i] * s[i];
    ++n;
  }
  const double a = PriorHalfWidth(ww, ss, n, sigma_mm);
  for (size_t i = 0; i < held.size(); ++i) {
    if (s[i] == 0.0 && w_obs[i] == 0.0) continue;
    held[i].w = a * ShrunkDepth(w_obs[i] / a, s[i] / a);
  }
  return held;
}

}  // namespace pfdm
