#include "pfdm/fit/problem/frame_terms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "ceres/ceres.h"
#include "glog/logging.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/directional_noise.h"
#include "pfdm/fit/problem/frame_blocks.h"
#include "pfdm/fit/problem/gauss_newton_step.h"
#include "pfdm/fit/problem/knot_coverage.h"
#include "pfdm/fit/residuals/apex_gauge_residual.h"
#include "pfdm/fit/residuals/axis_gauge_chain.h"
#include "pfdm/fit/residuals/data_cost.h"
#include "pfdm/fit/residuals/incompressibility_residual.h"
#include "pfdm/fit/residuals/meridian_gauge_residual.h"
#include "pfdm/fit/residuals/point_group_residual.h"
#include "pfdm/fit/residuals/point_residual.h"
#include "pfdm/fit/residuals/precomputed_groups.h"
#include "pfdm/fit/residuals/regularizer.h"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/fit/residuals/spin_gauge_residual.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// Points per grouped residual block: enough to amortize Ceres' per-block
// work, few enough to leave blocks for every thread.  A tracked 50,000-point
// frame took 31 ms an iteration with 512, 26.5 with 1,024 or 2,048 (one
// thread; with two, 18 whichever).
constexpr size_t kPointsPerGroup = 1024;

}  // namespace

std::unique_ptr<PrecomputedGroups> FrameProblem::MakePrecomputed(
    const FitOptions& options) {
  if (options.jacobian != JacobianKind::kAnalytic) return nullptr;
  return std::make_unique<PrecomputedGroups>(
      options.solver.num_threads,
      /*speculate=*/options.solver.kind != SolverKind::kIntegrator);
}

ceres::Problem::Options FrameProblem::ProblemOptions(
    PrecomputedGroups* precomputed) {
  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = precomputed;
  return problem_options;
}

void FrameProblem::AddData(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<MaterialPoint>& material,
                           const std::vector<Eigen::Vector3d>& normals) {
  const ModelConfig& config = model_->config;
  const KnotGrid grid = config.Grid();
  const bool analytic = precomputed_ != nullptr;
  const FunctionMask free_mask = config.FreeMask();
  const bool unit_exponents = model_->UnitExponents();
  const size_t group_size = loss_ == nullptr ? kPointsPerGroup : 1;
  std::vector<std::vector<PointSample>> groups(config.num_knots - 1);
  const size_t group_capacity = std::min(group_size, points.size());
  if (analytic) {
    for (auto& group : groups) group.reserve(group_capacity);
  }
  auto add_group = [&](int k0) {
    AddPointGroup(k0, std::move(groups[k0]));
    groups[k0] = {};
    groups[k0].reserve(group_capacity);
  };
  for (size_t i = 0; i < points.size(); ++i) {
    const KnotSpan span = grid.Span(material[i].u);
    const double u = material[i].u, v = material[i].v, w = material[i].w;
    const Eigen::Vector3d& normal = normals[i];
    const bool plane = normal != Eigen::Vector3d::Zero();
    if (analytic) {
      groups[span.k0].push_back(
          plane ? PointSample(points[i], u, v, span.weight, normal)
                : PointSample(points[i], u, v, span.weight));
      groups[span.k0].back().w = w;
      if (groups[span.k0].size() == group_size) add_group(span.k0);
      continue;
    }
    ceres::CostFunction* cost =
        plane ? MakeSurfaceCost(points[i], u, v, span.weight, free_mask,
                                unit_exponents, normal, options_.jacobian, w)
              : MakePointCost(points[i], u, v, span.weight, free_mask,
                              unit_exponents, options_.jacobian, w);
    data_ids_.push_back(blocks_.AddResidual(
        cost, loss_, true, {kGlobalsBlock, span.k0, span.k0 + 1}));
  }
  for (int k0 = 0; k0 + 1 < config.num_knots; ++k0) {
    if (!groups[k0].empty()) add_group(k0);
  }
}

void FrameProblem::AddPointGroup(int k0, std::vector<PointSample> group) {
  const std::array<const FreeEntries*, 3> entries = {
      blocks_.entries(kGlobalsBlock), blocks_.entries(k0),
      blocks_.entries(k0 + 1)};
  const std::array<bool, 5> varied = {true, true, entries[0] != nullptr,
                                      entries[1] != nullptr,
                                      entries[2] != nullptr};
  auto* residual =
      new PointGroupResidual(std::move(group), model_->config.FreeMask(),
                             model_->UnitExponents(), entries, varied);
  const ceres::ResidualBlockId id =
      blocks_.AddResidual(residual, loss_, true, {kGlobalsBlock, k0, k0 + 1},
                          FrameBlocks::Takes::kProblemBlocks);
  data_ids_.push_back(id);
  std::vector<double*> parameters;
  problem_.GetParameterBlocksForResidualBlock(id, &parameters);
  precomputed_->Add(residual, std::move(parameters));
}

void FrameProblem::AddSmoothness(size_t num_points) {
  if (options_.smoothness_weight <= 0.0) return;
  const double sqrt_weight =
      std::sqrt(options_.smoothness_weight * PointsPerKnot(num_points));
  const FunctionValues knot_scales = KnotScales();
  for (int k = 1; k + 1 < model_->config.num_knots; ++k) {
    smoothness_ids_.push_back(blocks_.AddResidual(
        SmoothnessResidual::Create(sqrt_weight, knot_scales), nullptr, false,
        {k - 1, k, k + 1}));
  }
}

void FrameProblem::AddRim(size_t num_points, double rim_height) {
  const ModelConfig& config = model_->config;
  // The rim's target in world terms, along the axis the solve starts from.
  const Eigen::Vector3d axis = model_->Rotation().col(2);
  const double top =
      axis.dot(Eigen::Vector3d(model_->state.center.data())) + rim_height;
  blocks_.AddResidual(
      RimResidual::Create(std::sqrt(PointsPerKnot(num_points)),
                          std::sin(config.u_max), axis, top, config.FreeMask()),
      nullptr, true, {kGlobalsBlock, config.num_knots - 1});
}

void FrameProblem::AddGauges(size_t num_points, const ModelState& reference) {
  const ModelConfig& config = model_->config;
  const double sqrt_weight = kGaugeWeight * std::sqrt(num_points);
  if (kind_ != FrameKind::kReference) {
    gauge_ids_.push_back(problem_.AddResidualBlock(
        SpinGaugeResidual::Create(sqrt_weight, SpinGaugeLength(*model_),
                                  reference.quaternion),
        nullptr, model_->state.quaternion.data()));
  } else if (options_.reference_spin_weight > 0.0) {
    gauge_ids_.push_back(problem_.AddResidualBlock(
        SpinGaugeResidual::Create(
            std::sqrt(options_.reference_spin_weight * num_points),
            SpinGaugeLength(*model_), reference.quaternion),
        nullptr, model_->state.quaternion.data()));
  }
  if (kind_ == FrameKind::kReference && options_.reference_apex_weight > 0.0) {
    AddApexGauge(num_points, reference);
  }
  if (kind_ == FrameKind::kUntracked &&
      config.modes[kA3] == FunctionMode::kFree) {
    for (int k = 0; k + 1 < config.num_knots; ++k) {
      gauge_ids_.push_back(
          blocks_.AddResidual(MeridianGaugeResidual::Create(
                                  sqrt_weight, model_->state.globals[kA0]),
                              nullptr, false, {k, k + 1}));
    }
  }
  if (config.modes[kE1o] == FunctionMode::kFree) AddAxisGauge(sqrt_weight);
}

void FrameProblem::AddApexGauge(size_t num_points,
                                const ModelState& reference) {
  const Model start{model_->config, reference};
  const Eigen::Vector3d axis = start.Rotation().col(2);
  const double height =
      axis.dot(Eigen::Vector3d(reference.center.data())) + ApexHeight(start);
  gauge_ids_.push_back(blocks_.AddResidual(
      ApexGaugeResidual::Create(
          std::sqrt(options_.reference_apex_weight * num_points),
          ApexExtent(*model_), axis, height),
      nullptr, true, {kGlobalsBlock}));
}

void FrameProblem::AddAxisGauge(double sqrt_weight) {
  const int num_knots = model_->config.num_knots;
  if (options_.solver.kind == SolverKind::kDirect &&
      kind_ == FrameKind::kTracked) {
    std::vector<const double*> knots;
    for (const FunctionValues& knot : model_->state.knots) {
      knots.push_back(knot.data());
    }
    axis_gauge_.emplace(knots, sqrt_weight);
    for (int k = 0; k < num_knots; ++k) {
      gauge_ids_.push_back(blocks_.AddResidual(axis_gauge_->Link(k),
                                               axis_gauge_->LinkSums(k), {k}));
    }
    gauge_ids_.push_back(problem_.AddResidualBlock(
        axis_gauge_->End(), nullptr, axis_gauge_->sum(num_knots - 1)));
    return;
  }
  std::vector<int> knots;
  for (int k = 0; k < num_knots; ++k) knots.push_back(k);
  gauge_ids_.push_back(blocks_.AddResidual(
      new AxisGaugeResidual(num_knots, sqrt_weight), nullptr, false, knots));
}

void FrameProblem::AddPrior(const std::vector<MaterialPoint>& material,
                            const ModelState& prior) {
  const size_t num_points = material.size();
  const double prior_weight = kind_ == FrameKind::kUntracked
                                  ? options_.untracked_prior_weight
                                  : options_.prior_weight;
  if (prior_weight <= 0.0) return;
  const ModelConfig& config = model_->config;
  const double sqrt_weight =
      std::sqrt(prior_weight * PointsPerKnot(num_points));
  FunctionValues knot_scales = KnotScales();
  FunctionValues global_scales =
      RegularizerScales(*model_, HeldEntries(config, kind_, kGlobalsBlock));
  if (kind_ == FrameKind::kUntracked &&
      !options_.untracked_prior_holds_length) {
    knot_scales[kA3] = global_scales[kA3] = 0.0;
  }
  // Where the points cover a ring, its radii are theirs; held at frame 0's
  // they read the LV phantom's radial contraction 1.6 points under.
  const std::vector<FunctionValues> scales =
      kind_ == FrameKind::kUntracked
          ? CoveredRadiiScales(config.Grid(), material, knot_scales,
                               options_.untracked_prior_covered_radii_scale)
          : std::vector<FunctionValues>(config.num_knots, knot_scales);
  for (int k = 0; k < config.num_knots; ++k) {
    prior_ids_.push_back(blocks_.AddResidual(
        PriorResidual::Create(sqrt_weight, scales[k], prior.knots[k]), nullptr,
        false, {k}));
  }
  prior_ids_.push_back(blocks_.AddResidual(
      PriorResidual::Create(std::sqrt(prior_weight * num_points), global_scales,
                            prior.globals),
      nullptr, false, {kGlobalsBlock}));
}

void FrameProblem::AddIncompressibility(size_t num_points,
                                        const ModelState& reference) {
  const ModelConfig& config = model_->config;
  if (options_.incompressible_weight <= 0.0 || !config.Solid() ||
      kind_ == FrameKind::kReference) {
    return;
  }
  const Model before{config, reference};
  double thickness = 0.0;
  for (int k = 0; k < config.num_knots; ++k) {
    thickness += before.FunctionAt(kH, config.Grid().KnotU(k));
  }
  thickness /= config.num_knots;
  double u_low = options_.incompressible_u_low;
  double u_high = options_.incompressible_u_high;
  if (u_low >= u_high) {
    u_low = config.u_min;
    u_high = config.u_max;
  }
  std::vector<int> blocks = {kGlobalsBlock};
  for (int k = 0; k < config.num_knots; ++k) blocks.push_back(k);
  incompressibility_id_ = blocks_.AddResidual(
      IncompressibilityResidual::Create(
          config, model_->UnitExponents(), u_low, u_high,
          std::sqrt(options_.incompressible_weight * num_points),
          IncompressibilityVolume(before, u_low, u_high), thickness),
      nullptr, false, blocks);
}

SolverReport FrameProblem::Solve() {
  SolverOptions solver = options_.solver;
  // The groups' threads are PrecomputedGroups'; Ceres' own would only copy
  // the results, and waking them cost more than that at a few thousand
  // points.
  if (precomputed_) solver.num_threads = 1;
  solver.hold_bounds = kind_ != FrameKind::kReference;  // solver.h says why.
  if (solver.kind == SolverKind::kIntegrator) {
    AddDampingScales(problem_, blocks_, options_.damping_groups, model_,
                     &solver);
  }
  if (solver.on_step) {
    solver.on_step = [this,
                      observe = solver.on_step](const SolverTracePoint& point) {
      blocks_.Store();
      observe(point);
    };
  }
  SolverReport report = SolveProblem(&problem_, solver);
  blocks_.Store();
  return report;
}

TermCosts FrameProblem::Costs(const SolverReport& report) const {
  TermCosts costs;
  costs.smoothness = CostOf(smoothness_ids_);
  costs.prior = CostOf(prior_ids_);
  costs.gauge = CostOf(gauge_ids_);
  costs.incompressibility = CostOf({incompressibility_id_});
  const double total = report.trace.empty() ? 0.0 : report.trace.back().cost;
  costs.data = std::max(0.0, total - costs.smoothness - costs.prior -
                                 costs.gauge - costs.incompressibility);
  return costs;
}

std::vector<CovarianceBlock> FrameProblem::CovarianceBlocks() {
  using Kind = CovarianceEntry::Kind;
  std::vector<CovarianceBlock> blocks;
  ModelState& state = model_->state;
  const std::array<std::pair<double*, Kind>, 2> pose = {
      {{state.center.data(), Kind::kCenter},
       {state.quaternion.data(), Kind::kRotation}}};
  for (const auto& [parameters, kind] : pose) {
    if (problem_.IsParameterBlockConstant(parameters)) continue;
    CovarianceBlock block{parameters, {}};
    for (int axis = 0; axis < 3; ++axis) {
      block.entries.push_back({kind, -1, axis});
    }
    blocks.push_back(std::move(block));
  }
  for (int b = kGlobalsBlock; b < model_->config.num_knots; ++b) {
    const FreeEntries* entries = blocks_.entries(b);
    if (entries == nullptr) continue;
    CovarianceBlock block{blocks_.parameters(b), {}};
    const Kind kind = b == kGlobalsBlock ? Kind::kGlobal : Kind::kKnot;
    for (int f : entries->free()) block.entries.push_back({kind, b, f});
    blocks.push_back(std::move(block));
  }
  return blocks;
}

FrameCovariance FrameProblem::Covariance(
    const FrameInputs& frame, const std::vector<Eigen::Vector3d>* wall_normals,
    bool depths_held) {
  const auto start = Clock::now();
  FrameCovariance result = ScaledCovariance(frame, wall_normals, depths_held);
  result.seconds = SecondsSince(start);
  return result;
}

FrameCovariance FrameProblem::ScaledCovariance(
    const FrameInputs& frame, const std::vector<Eigen::Vector3d>* wall_normals,
    bool depths_held) {
  // sigma's degrees of freedom need the covariance's effective number of
  // parameters: computed at unit sigma, then scaled.
  NormalParts parts;
  FrameCovariance result =
      BlockCovariance(&problem_, CovarianceBlocks(), 1.0, 0.0, data_ids_,
                      wall_normals != nullptr ? &parts : nullptr);
  if (!result.computed) return result;
  DataSigma(*model_, frame.points, frame.material, frame.normals, options_.loss,
            options_.loss_scale_mm, result.effective_parameters,
            &result.sigma_mm, &result.degrees_of_freedom);
  result.unit_covariance = result.covariance;
  result.covariance *= result.sigma_mm * result.sigma_mm;
  if (wall_normals == nullptr) return result;
  // The data's J'J along the wall normals, for each direction's share of
  // the parameters: the same problem, every point pulling along its
  // normal (its groups' moments, as the solve's).
  const FrameInputs along{frame.points,     frame.material, *wall_normals,
                          frame.rim_height, frame.kind,     frame.prior,
                          frame.reference};
  Model at = *model_;
  FrameProblem across(kind_, options_, &at);
  BuildFrameProblem(along, &across);
  const Eigen::MatrixXd normal_data_normal = DataNormalMatrix(
      &across.problem_, across.CovarianceBlocks(), across.data_ids_);
  // Built alike, it has the same columns; a problem that cannot be
  // evaluated has none.
  if (normal_data_normal.cols() != parts.pseudo_inverse.cols()) return result;
  ScaleByDirectionalNoise(parts, normal_data_normal, *model_, frame.points,
                          frame.material, *wall_normals, options_.loss,
                          options_.loss_scale_mm, depths_held, &result);
  return result;
}

double FrameProblem::CostOf(
    const std::vector<ceres::ResidualBlockId>& ids) const {
  double cost = 0.0;
  std::vector<double*> parameters;
  for (ceres::ResidualBlockId id : ids) {
    if (id == nullptr) continue;
    const ceres::CostFunction* function =
        problem_.GetCostFunctionForResidualBlock(id);
    problem_.GetParameterBlocksForResidualBlock(id, &parameters);
    Eigen::VectorXd residuals(function->num_residuals());
    if (function->Evaluate(parameters.data(), residuals.data(), nullptr)) {
      cost += 0.5 * residuals.squaredNorm();
    }
  }
  return cost;
}

void BuildFrameProblem(const FrameInputs& frame, FrameProblem* problem) {
  CHECK_EQ(frame.normals.size(), frame.points.size());
  const size_t num_points = frame.points.size();
  problem->AddData(frame.points, frame.material, frame.normals);
  problem->AddSmoothness(num_points);
  if (frame.rim_height) problem->AddRim(num_points, *frame.rim_height);
  problem->AddGauges(num_points, frame.reference);
  problem->AddPrior(frame.material, frame.prior);
  problem->AddIncompressibility(num_points, frame.reference);
}

}  // namespace pfdm
