#include "pfdm/fit/correspondence/measured_depths.h"

#include <algorithm>
#include <cmath>

#include "pfdm/model/transmural.h"

namespace pfdm {
namespace {

constexpr int kNewtonSteps = 8;

// The layer w whose offset is d, f the functions at the tag's u.
double DepthOfOffset(const FunctionValues& f, double d) {
  const double h = f[kH];
  if (!(h > 0.0)) return 0.0;
  double w = std::clamp(2.0 * d / h, -kMaxMeasuredDepth, kMaxMeasuredDepth);
  for (int step = 0; step < kNewtonSteps; ++step) {
    const double slope = 0.5 * h + 2.0 * w * f[kWallShift] +
                         (3.0 * w * w - 1.0) * f[kWallSqueeze];
    if (!(slope > 0.0)) break;  // Layers folded: keep the last w.
    w = std::clamp(w - (WallDepth(f.data(), w) - d) / slope, -kMaxMeasuredDepth,
                   kMaxMeasuredDepth);
  }
  return w;
}

}  // namespace

bool HasBothWalls(const Frame& frame) {
  const auto on = [&frame](WallLayer layer) {
    return std::any_of(
        frame.points.begin(), frame.points.end(),
        [layer](const DataPoint& p) { return p.layer == layer; });
  };
  return on(WallLayer::kEndocardium) && on(WallLayer::kEpicardium);
}

bool HasBothWalls(const std::vector<double>& layer_w) {
  return std::count(layer_w.begin(), layer_w.end(), -1.0) > 0 &&
         std::count(layer_w.begin(), layer_w.end(), 1.0) > 0;
}

std::vector<double> MeasuredDepths(const Model& model,
                                   const std::vector<MaterialPoint>& material,
                                   const std::vector<double>& distances) {
  std::vector<double> depths(material.size(), 0.0);
  for (size_t i = 0; i < material.size(); ++i) {
    depths[i] = DepthOfOffset(model.FunctionsAt(material[i].u), distances[i]);
  }
  return depths;
}

}  // namespace pfdm
