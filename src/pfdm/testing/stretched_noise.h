// Tracked tags' residuals on a frame that moved since frame 0: frame 0's
// noise moves each tag's material point (u, v), which the later frame
// carries stretched; the later frame adds its own.
#ifndef PFDM_TESTING_STRETCHED_NOISE_H_
#define PFDM_TESTING_STRETCHED_NOISE_H_

#include <random>
#include <vector>

#include "Eigen/Core"
#include "Eigen/QR"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// `first` with its radii across the axis (a1, a2) `scale` times as long.
inline Model RadiallyScaled(const Model& first, double scale) {
  Model later = first;
  for (FunctionValues& knot : later.state.knots) {
    knot[kA1] *= scale;
    knot[kA2] *= scale;
  }
  return later;
}

// At each material point: frame 0's noise of sigma_mm per coordinate taken
// to (u, v) by `first`'s tangents and out by `later`'s, plus `later`'s own
// noise of sigma_mm per coordinate.
inline std::vector<Eigen::Vector3d> StretchedTagResiduals(
    const Model& first, const Model& later,
    const std::vector<MaterialPoint>& material, double sigma_mm,
    unsigned seed) {
  const std::vector<Eigen::Matrix<double, 3, 2>> from =
      SurfaceTangents(first, material);
  const std::vector<Eigen::Matrix<double, 3, 2>> to =
      SurfaceTangents(later, material);
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma_mm);
  std::vector<Eigen::Vector3d> residuals;
  for (size_t i = 0; i < material.size(); ++i) {
    const Eigen::Vector3d e0(noise(random), noise(random), noise(random));
    const Eigen::Vector2d duv = from[i].colPivHouseholderQr().solve(e0);
    residuals.push_back(to[i] * duv + Eigen::Vector3d(noise(random),
                                                      noise(random),
                                                      noise(random)));
  }
  return residuals;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_STRETCHED_NOISE_H_
