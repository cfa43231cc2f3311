// One frame's problem for fixed material points: the data residuals, the
// regularizer and the gauge terms over the frame's blocks, solved by the
// chosen solver.
#ifndef PFDM_FIT_PROBLEM_FRAME_PROBLEM_H_
#define PFDM_FIT_PROBLEM_FRAME_PROBLEM_H_

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// Each term's share of a frame problem's cost at the solution (1/2 the sum
// of its squared residuals): what the data say against what the
// regularizer and the gauge impose.
struct TermCosts {
  double data = 0.0;  // With the base rim's.
  double smoothness = 0.0;
  double prior = 0.0;
  double gauge = 0.0;
  double incompressibility = 0.0;  // --incompressible.
  double Total() const {
    return data + smoothness + prior + gauge + incompressibility;
  }
};

// What a frame's problem is made of: the points and their material
// points; a point with a non-zero normal (unit, world frame) pulls along it
// (point-to-plane), the others with their whole distance, sliding points
// taking theirs from the search that found their material points on the
// model, or from SlidingNormals (correspondence.h).  rim_height, when
// given, is where the base rim must sit (RimResidual), along the model's
// axis from its centre as the solve starts.  `prior` is the state the
// prior term pulls toward (the previous frame's; frame 0's for untracked
// frames, with FitOptions::untracked_prior_weight); `reference` frame 0's
// state: its pose, which later frames may not spin away from
// (SpinGaugeResidual), and a solid's wall volume, which later frames keep
// with FitOptions::incompressible_weight.  Every member is the caller's and
// outlives the call it is passed to.
struct FrameInputs {
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<MaterialPoint>& material;
  const std::vector<Eigen::Vector3d>& normals;
  std::optional<double> rim_height;
  FrameKind kind;
  const ModelState& prior;
  const ModelState& reference;
};

// Solves the frame from *model, leaving the solution there and, when
// given, each term's cost in *costs.
SolverReport SolveFrame(const FrameInputs& frame, const FitOptions& options,
                        Model* model, TermCosts* costs = nullptr);

// One Levenberg-Marquardt step of the same problem from *model, left in
// it (TakeGaussNewtonStep: the direct solve's first iteration); false, the
// model unmoved, if Ceres would not keep it.  `verify`, when given, sees
// the stepped model and says whether that test (an evaluation of the
// frame) is needed; without it, it always is.
bool StepFrame(const FrameInputs& frame, const FitOptions& options,
               Model* model,
               const std::function<bool(const Model&)>& verify = nullptr);

// The covariance of the frame's free parameters at `model` (a solution of
// SolveFrame with the same inputs), from the same problem, not solved
// again (frame_covariance.h says what it is and is not).  A solid's frame of
// tracked tags alone weighs its data by the residual's sd across the
// wall's normal, where the tags' depths do not err, and, with
// `depths_held` (frame 0's, FrameFit::depths_held), its rows along the
// normal take the excess of the residuals' variance along it, where frame
// 0's noise is (directional_noise.h).
FrameCovariance EstimateFrameCovariance(const FrameInputs& frame,
                                        const FitOptions& options,
                                        const Model& model,
                                        bool depths_held = false);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_FRAME_PROBLEM_H_
