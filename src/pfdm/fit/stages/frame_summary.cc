#include "pfdm/fit/stages/frame_summary.h"

#include <algorithm>
#include <cmath>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

bool StateFinite(const ModelState& state) {
  auto finite = [](const auto& values) {
    for (double v : values) {
      if (!std::isfinite(v)) return false;
    }
    return true;
  };
  if (!finite(state.center) || !finite(state.quaternion) ||
      !finite(state.globals)) {
    return false;
  }
  for (const FunctionValues& knot : state.knots) {
    if (!finite(knot)) return false;
  }
  return finite(state.local.values) && finite(state.local.slope);
}

}  // namespace

void Summarize(const Model& model, const std::vector<Eigen::Vector3d>& points,
               FrameFit* fit) {
  double sum_squared = 0.0, sum = 0.0, max = 0.0;
  fit->residuals = Residuals(model, points, fit->material);
  for (const Eigen::Vector3d& r : fit->residuals) {
    sum_squared += r.squaredNorm();
    sum += r.norm();
    max = std::max(max, r.norm());
  }
  fit->rms_mm = std::sqrt(sum_squared / points.size());
  fit->mean_distance_mm = sum / points.size();
  fit->max_distance_mm = max;
  fit->state = model.state;
}

void CheckFinite(const std::string& source, const FrameFit& fit) {
  if (std::isfinite(fit.rms_mm) && std::isfinite(fit.max_distance_mm) &&
      StateFinite(fit.state)) {
    return;
  }
  throw InputError(source + ": frame " + std::to_string(fit.frame) +
                   ": the fit diverged (its error is not finite)");
}

}  // namespace pfdm
