#include "pfdm/fit/problem/gauge.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "pfdm/fit/correspondence/correspondence.h"

namespace pfdm {
namespace {

constexpr int kReferenceHeld[] = {kA3, kTau, kDtau, kWallShift,
                                  kB0, kB1,  kB2,   kB3};

}  // namespace

std::vector<int> HeldEntries(const ModelConfig& config, FrameKind kind,
                             int block) {
  const bool reference = kind == FrameKind::kReference;
  const FunctionMode fitted =
      block == kGlobalsBlock ? FunctionMode::kConstant : FunctionMode::kFree;
  std::vector<int> held;
  for (int f = 0; f < kNumFunctions; ++f) {
    bool hold = config.modes[f] != fitted;
    if (reference) {
      hold = hold ||
             std::find(std::begin(kReferenceHeld), std::end(kReferenceHeld),
                       f) != std::end(kReferenceHeld);
    }
    hold = hold || ((f == kE1o || f == kE2o) && block == kGlobalsBlock);
    if (kind == FrameKind::kUntracked) {
      hold = hold || f == kTau || f == kDtau || f == kWallShift;
    }
    if (hold) held.push_back(f);
  }
  return held;
}

double SpinGaugeLength(const Model& model) {
  return model.state.globals[kA0] * 0.5 *
         (model.FunctionAt(kA1, 0.0) + model.FunctionAt(kA2, 0.0));
}

double TopHeight(const std::vector<Eigen::Vector3d>& points,
                 const FitOptions& options, const Model& model) {
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const Eigen::Vector3d center(model.state.center.data());
  std::vector<MaterialPoint> closest;
  if (options.loss != "none") closest = ClosestMaterialPoints(model, points);
  double top = std::numeric_limits<double>::quiet_NaN();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!closest.empty() &&
        (model.WorldPoint(closest[i].u, closest[i].v) - points[i]).norm() >
            3.0 * options.loss_scale_mm) {
      continue;
    }
    const double z = (points[i] - center).dot(axis);
    if (!(z <= top)) top = z;
  }
  return top;
}

void SpanAxialExtent(const std::vector<Eigen::Vector3d>& points,
                     const FitOptions& options, Model* model) {
  const double z_base = TopHeight(points, options, *model);
  if (!std::isfinite(z_base)) return;
  const Eigen::Vector3d axis = model->Rotation().col(2);
  const Eigen::Vector3d center(model->state.center.data());
  const double sin_min = std::sin(model->config.u_min);
  const double sin_max = std::sin(model->config.u_max);
  FunctionValues& globals = model->state.globals;
  const double a0 = globals[kA0];
  const double a3 = model->FunctionAt(kA3, model->config.u_min);
  const double z_apex = a0 * a3 * sin_min;
  const double new_a0 = (z_base - z_apex) / (a3 * (sin_max - sin_min));
  const Eigen::Vector3d new_center =
      center + axis * (z_apex - new_a0 * a3 * sin_min);
  for (int i = 0; i < 3; ++i) model->state.center[i] = new_center[i];
  auto rescale = [&](FunctionValues& values) {
    values[kA1] *= a0 / new_a0;
    values[kA2] *= a0 / new_a0;
  };
  rescale(globals);
  for (FunctionValues& knot : model->state.knots) rescale(knot);
  globals[kA0] = new_a0;
}

}  // namespace pfdm
