// One frame's ceres::Problem, term by term (frame_problem.h solves it).
#ifndef PFDM_FIT_PROBLEM_FRAME_TERMS_H_
#define PFDM_FIT_PROBLEM_FRAME_TERMS_H_

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ceres/ceres.h"
#include "pfdm/fit/problem/frame_blocks.h"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/problem/gauss_newton_step.h"
#include "pfdm/fit/residuals/axis_gauge_chain.h"
#include "pfdm/fit/residuals/precomputed_groups.h"
#include "pfdm/fit/residuals/regularizer.h"
#include "pfdm/fit/residuals/robust_loss.h"

namespace pfdm {

// One frame's ceres::Problem as it is built up, term by term, and solved.
// The terms go in a fixed order (data, smoothness, rim, gauges, prior, the
// wall's volume): Ceres sums in the order residual blocks were added, so
// the order is part of the result to the last bit.
class FrameProblem {
 public:
  FrameProblem(FrameKind kind, const FitOptions& options, Model* model)
      : kind_(kind),
        options_(options),
        model_(model),
        precomputed_(MakePrecomputed(options)),
        problem_(ProblemOptions(precomputed_.get())),
        blocks_(kind, model, &problem_) {}

  // The data residuals: analytic points go into PointGroupResidual blocks,
  // which take the problem's blocks as they are: many points between the
  // same two knots, or one each when every point carries its own robust
  // loss.  Those are evaluated ahead of Ceres (precomputed_groups.h), on the
  // threads, each trust-region candidate with its Jacobians (the
  // integrator, which calls Problem::Evaluate, has no candidates).
  void AddData(const std::vector<Eigen::Vector3d>& points,
               const std::vector<MaterialPoint>& material,
               const std::vector<Eigen::Vector3d>& normals);
  void AddSmoothness(size_t num_points);
  // Where the base rim must sit (RimResidual), along the model's axis from
  // its centre as the solve starts.
  void AddRim(size_t num_points, double rim_height);
  void AddGauges(size_t num_points, const ModelState& reference);
  void AddPrior(const std::vector<MaterialPoint>& material,
                const ModelState& prior);
  // A solid's wall keeps the reference's volume (after frame 0, with
  // FitOptions::incompressible_weight).
  void AddIncompressibility(size_t num_points, const ModelState& reference);
  // Solves with the chosen solver and leaves the solution in the model.
  SolverReport Solve();
  // One step from the model's values (TakeGaussNewtonStep), left in it;
  // `verify` sees the stepped model.
  bool Step(const std::function<bool(const Model&)>& verify) {
    const bool kept =
        TakeGaussNewtonStep(kInitialTrustRegionRadius, &problem_, [&] {
          blocks_.Store();
          return !verify || verify(*model_);
        });
    blocks_.Store();
    return kept;
  }
  // Each term's cost at the parameters' current values, the data's as the
  // rest of the solve's final cost.
  TermCosts Costs(const SolverReport& report) const;
  // The free parameters' covariance at their current values; with
  // wall_normals (a frame of tracked tags alone), its data's rows weighed
  // by the residual's sd across them, and with depths_held the rows
  // along them take the excess of the variance along them too
  // (directional_noise.h).  Its seconds
  // are all of this call's.
  FrameCovariance Covariance(
      const FrameInputs& frame,
      const std::vector<Eigen::Vector3d>* wall_normals = nullptr,
      bool depths_held = false);

 private:
  FrameCovariance ScaledCovariance(
      const FrameInputs& frame,
      const std::vector<Eigen::Vector3d>* wall_normals, bool depths_held);
  std::vector<CovarianceBlock> CovarianceBlocks();
  static std::unique_ptr<PrecomputedGroups> MakePrecomputed(
      const FitOptions& options);
  static ceres::Problem::Options ProblemOptions(PrecomputedGroups* precomputed);
  void AddPointGroup(int k0, std::vector<PointSample> group);
  void AddAxisGauge(double sqrt_weight);
  // Frame 0's apex toward the start's (FitOptions::reference_apex_weight).
  void AddApexGauge(size_t num_points, const ModelState& reference);
  // 1/2 the sum of the blocks' squared residuals (no loss: the terms other
  // than the data have none).
  double CostOf(const std::vector<ceres::ResidualBlockId>& ids) const;
  double PointsPerKnot(size_t num_points) const {
    return static_cast<double>(num_points) / model_->config.num_knots;
  }
  FunctionValues KnotScales() const {
    return RegularizerScales(
        *model_, HeldEntries(model_->config, FrameKind::kTracked, 0));
  }

  const FrameKind kind_;
  const FitOptions& options_;
  Model* model_;
  // Evaluates the analytic point groups; null for the other Jacobians.
  std::unique_ptr<PrecomputedGroups> precomputed_;
  ceres::Problem problem_;
  FrameBlocks blocks_;
  // Owned by problem_.
  ceres::LossFunction* loss_ = MakeLoss(options_.loss, options_.loss_scale_mm);
  // The axis gauge's partial sums, parameter blocks of the problem.
  std::optional<AxisGaugeChain> axis_gauge_;
  // The residual blocks of each term but the data (null: a constant left
  // out, see FrameBlocks::AddResidual).
  std::vector<ceres::ResidualBlockId> smoothness_ids_, prior_ids_, gauge_ids_;
  ceres::ResidualBlockId incompressibility_id_ = nullptr;
  // The data's residual blocks, the problem's first (the covariance's
  // effective number of parameters).
  std::vector<ceres::ResidualBlockId> data_ids_;
};

// The frame's terms, as SolveFrame adds them.
void BuildFrameProblem(const FrameInputs& frame, FrameProblem* problem);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_FRAME_TERMS_H_
