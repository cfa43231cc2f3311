#include "pfdm/fit/stages/frame_uncertainty.h"

#include <cmath>
#include <optional>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/fit/stages/top_slice.h"

namespace pfdm {

FrameCovariance MeasureFrameCovariance(
    const FramePoints& points, const std::vector<MaterialPoint>& material,
    const ModelState& prior, const ModelState& reference,
    const FitOptions& options, const Model& model, bool depths_held) {
  // As GlobalRounds::SolveRound: sliding points pull along the normals at
  // their material points, and the base rim holds later frames of contours.
  std::optional<double> rim_height;
  if (points.kind != FrameKind::kReference && !points.untracked.empty()) {
    const double top = TopHeight(points.positions, options, model);
    const bool top_is_slice =
        model.config.Solid() && TopIsSlice(points.positions, model);
    if (std::isfinite(top)) rim_height = top + RimLift(top_is_slice, model);
  }
  const std::vector<Eigen::Vector3d> normals =
      SlidingNormals(model, material, points.sliding);
  return EstimateFrameCovariance({points.positions, material, normals,
                                  rim_height, points.kind, prior, reference},
                                 options, model, depths_held);
}

}  // namespace pfdm
