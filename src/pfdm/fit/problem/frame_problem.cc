#include "pfdm/fit/problem/frame_problem.h"

#include <algorithm>
#include <functional>
#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/frame_terms.h"

namespace pfdm {

SolverReport SolveFrame(const FrameInputs& frame, const FitOptions& options,
                        Model* model, TermCosts* costs) {
  FrameProblem problem(frame.kind, options, model);
  BuildFrameProblem(frame, &problem);
  SolverReport report = problem.Solve();
  if (costs != nullptr) *costs = problem.Costs(report);
  return report;
}

bool StepFrame(const FrameInputs& frame, const FitOptions& options,
               Model* model, const std::function<bool(const Model&)>& verify) {
  FrameProblem problem(frame.kind, options, model);
  BuildFrameProblem(frame, &problem);
  return problem.Step(verify);
}

FrameCovariance EstimateFrameCovariance(const FrameInputs& frame,
                                        const FitOptions& options,
                                        const Model& model, bool depths_held) {
  // The problem holds pointers into the model's state; Ceres only
  // evaluates it here, but the copy keeps the caller's model out of reach.
  Model at = model;
  FrameProblem problem(frame.kind, options, &at);
  BuildFrameProblem(frame, &problem);
  // Tracked tags alone in a solid, three rows a point, whose ranked depths
  // err along the wall's normal.  On one surface a tag's depth is the
  // surface's own.
  const bool ranked_tags =
      frame.kind == FrameKind::kTracked && model.config.Solid() &&
      std::all_of(frame.normals.begin(), frame.normals.end(),
                  [](const Eigen::Vector3d& n) { return n.isZero(); });
  if (!ranked_tags) return problem.Covariance(frame);
  const std::vector<Eigen::Vector3d> wall_normals =
      SurfaceNormals(model, frame.material);
  return problem.Covariance(frame, &wall_normals, depths_held);
}

}  // namespace pfdm
