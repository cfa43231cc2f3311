#include "pfdm/fit/frame_problem.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "ceres/ceres.h"
#include "glog/logging.h"
#include "pfdm/fit/axis_gauge_chain.h"
#include "pfdm/fit/correspondence.h"
#include "pfdm/fit/data_cost.h"
#include "pfdm/fit/frame_blocks.h"
#include "pfdm/fit/meridian_gauge_residual.h"
#include "pfdm/fit/point_group_residual.h"
#include "pfdm/fit/point_residual.h"
#include "pfdm/fit/precomputed_groups.h"
#include "pfdm/fit/regularizer.h"
#include "pfdm/fit/spin_gauge_residual.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Points per grouped residual block: enough to amortize Ceres' per-block
// work, few enough to leave blocks for every thread.  A tracked 50,000-point
// frame took 31 ms an iteration with 512, 26.5 with 1,024 or 2,048 (one
// thread; with two, 18 whichever).
constexpr size_t kPointsPerGroup = 1024;

// Millimetres of model-point motion per unit of each function, for the
// regularizers.  Everything scales with the data, so scaled data get scaled
// lengths.  tau is weighted as if at radius a0, about four times the LV's:
// near the apex the rings are too small for the data to pin the twist, and
// twist varies slowly along the axis, so its smoothness carries more.
FunctionValues FunctionScales(const Model& model,
                              const std::vector<int>& held) {
  const double a0 = model.state.globals[kA0];
  const double radius =
      a0 * 0.5 * (model.FunctionAt(kA1, 0.0) + model.FunctionAt(kA2, 0.0));
  FunctionValues scales{};
  scales[kA0] = 1.0;
  scales[kA1] = scales[kA2] = scales[kA3] = a0;
  scales[kEps1] = scales[kEps2] = radius;
  scales[kTau] = a0;
  scales[kB0] = scales[kB2] = scales[kE1o] = scales[kE2o] = scales[kE3o] = 1.0;
  scales[kB1] = scales[kB3] = radius;
  // A unit of h moves a wall surface by half a millimetre, one of shift by a
  // millimetre; dtau turns it by half as much as tau.
  scales[kH] = 0.5;
  scales[kWallShift] = 1.0;
  scales[kDtau] = 0.5 * a0;
  for (int f : held) scales[f] = 0.0;
  return scales;
}

// The groups' multipliers per free entry of each free block, and for the
// pose when it is free.
void AddDampingScales(const ceres::Problem& problem, const FrameBlocks& blocks,
                      const DampingGroups& groups, Model* model,
                      SolverOptions* solver) {
  blocks.ForEachFree([&](double* block, const std::vector<int>& free) {
    std::vector<double>& scales = solver->damping_scale[block];
    for (int f : free) scales.push_back(groups.Of(Function(f)));
  });
  for (double* pose :
       {model->state.center.data(), model->state.quaternion.data()}) {
    if (problem.IsParameterBlockConstant(pose)) continue;
    solver->damping_scale[pose].assign(problem.ParameterBlockTangentSize(pose),
                                       groups.pose);
  }
}

ceres::LossFunction* MakeLoss(const FitOptions& options) {
  if (options.loss == "none") return nullptr;
  if (options.loss == "huber")
    return new ceres::HuberLoss(options.loss_scale_mm);
  if (options.loss == "cauchy") {
    return new ceres::CauchyLoss(options.loss_scale_mm);
  }
  throw InputError("unknown --loss '" + options.loss +
                   "' (expected none, huber or cauchy)");
}

}  // namespace

SolverReport SolveFrame(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<MaterialPoint>& material,
                        const std::vector<Eigen::Vector3d>& normals,
                        std::optional<double> rim_height, FrameKind kind,
                        const ModelState& prior,
                        const std::array<double, 4>& reference_quaternion,
                        const FitOptions& options, Model* model) {
  CHECK_EQ(normals.size(), points.size());
  const ModelConfig& config = model->config;
  const KnotGrid grid = config.Grid();
  // Analytic points go into PointGroupResidual blocks, which take the
  // problem's blocks as they are: many points between the same two knots,
  // or one each when every point carries its own robust loss.  Those are
  // evaluated ahead of Ceres (precomputed_groups.h), on the threads, each
  // trust-region candidate with its Jacobians (the integrator, which calls
  // Problem::Evaluate, has no candidates).
  const bool analytic = options.jacobian == JacobianKind::kAnalytic;
  std::unique_ptr<PrecomputedGroups> precomputed;
  ceres::Problem::Options problem_options;
  if (analytic) {
    precomputed = std::make_unique<PrecomputedGroups>(
        options.solver.num_threads,
        /*speculate=*/options.solver.kind != SolverKind::kIntegrator);
    problem_options.evaluation_callback = precomputed.get();
  }
  ceres::Problem problem(problem_options);
  FrameBlocks blocks(kind, model, &problem);
  const bool reference = kind == FrameKind::kReference;

  ceres::LossFunction* loss = MakeLoss(options);
  const FunctionMask free_mask = config.FreeMask();
  const bool unit_exponents = model->UnitExponents();
  const size_t group_size = loss == nullptr ? kPointsPerGroup : 1;
  std::vector<std::vector<PointSample>> groups(config.num_knots - 1);
  const size_t group_capacity = std::min(group_size, points.size());
  if (analytic) {
    for (auto& group : groups) group.reserve(group_capacity);
  }
  auto add_group = [&](int k0) {
    const std::array<const FreeEntries*, 3> entries = {
        blocks.entries(kGlobalsBlock), blocks.entries(k0),
        blocks.entries(k0 + 1)};
    const std::array<bool, 5> varied = {true, true, entries[0] != nullptr,
                                        entries[1] != nullptr,
                                        entries[2] != nullptr};
    auto* group = new PointGroupResidual(std::move(groups[k0]), free_mask,
                                         unit_exponents, entries, varied);
    const ceres::ResidualBlockId id =
        blocks.AddResidual(group, loss, true, {kGlobalsBlock, k0, k0 + 1},
                           FrameBlocks::Takes::kProblemBlocks);
    if (precomputed) {
      std::vector<double*> parameters;
      problem.GetParameterBlocksForResidualBlock(id, &parameters);
      precomputed->Add(group, std::move(parameters));
    }
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
                                unit_exponents, normal, options.jacobian, w)
              : MakePointCost(points[i], u, v, span.weight, free_mask,
                              unit_exponents, options.jacobian, w);
    blocks.AddResidual(cost, loss, true, {kGlobalsBlock, span.k0, span.k0 + 1});
  }
  for (int k0 = 0; k0 + 1 < config.num_knots; ++k0) {
    if (!groups[k0].empty()) add_group(k0);
  }

  const double points_per_knot =
      static_cast<double>(points.size()) / config.num_knots;
  const FunctionValues knot_scales =
      FunctionScales(*model, HeldEntries(config, FrameKind::kTracked, 0));
  if (options.smoothness_weight > 0.0) {
    const double sqrt_weight =
        std::sqrt(options.smoothness_weight * points_per_knot);
    for (int k = 1; k + 1 < config.num_knots; ++k) {
      blocks.AddResidual(SmoothnessResidual::Create(sqrt_weight, knot_scales),
                         nullptr, false, {k - 1, k, k + 1});
    }
  }
  if (rim_height) {
    // The rim's target in world terms, along the axis the solve starts from.
    const Eigen::Vector3d axis = model->Rotation().col(2);
    const double top =
        axis.dot(Eigen::Vector3d(model->state.center.data())) + *rim_height;
    blocks.AddResidual(
        RimResidual::Create(std::sqrt(points_per_knot), std::sin(config.u_max),
                            axis, top, free_mask),
        nullptr, true, {kGlobalsBlock, config.num_knots - 1});
  }
  if (!reference) {
    problem.AddResidualBlock(SpinGaugeResidual::Create(
                                 kGaugeWeight * std::sqrt(points.size()),
                                 SpinGaugeLength(*model), reference_quaternion),
                             nullptr, model->state.quaternion.data());
  }
  if (kind == FrameKind::kUntracked &&
      config.modes[kA3] == FunctionMode::kFree) {
    for (int k = 0; k + 1 < config.num_knots; ++k) {
      blocks.AddResidual(
          MeridianGaugeResidual::Create(kGaugeWeight * std::sqrt(points.size()),
                                        model->state.globals[kA0]),
          nullptr, false, {k, k + 1});
    }
  }
  std::optional<AxisGaugeChain> axis_gauge;
  if (config.modes[kE1o] == FunctionMode::kFree) {
    const double sqrt_weight = kGaugeWeight * std::sqrt(points.size());
    if (options.solver.kind == SolverKind::kDirect &&
        kind == FrameKind::kTracked) {
      std::vector<const double*> knots;
      for (const FunctionValues& knot : model->state.knots) {
        knots.push_back(knot.data());
      }
      axis_gauge.emplace(knots, sqrt_weight);
      for (int k = 0; k < config.num_knots; ++k) {
        blocks.AddResidual(axis_gauge->Link(k), axis_gauge->LinkSums(k), {k});
      }
      problem.AddResidualBlock(axis_gauge->End(), nullptr,
                               axis_gauge->sum(config.num_knots - 1));
    } else {
      std::vector<int> knots;
      for (int k = 0; k < config.num_knots; ++k) knots.push_back(k);
      blocks.AddResidual(new AxisGaugeResidual(config.num_knots, sqrt_weight),
                         nullptr, false, knots);
    }
  }
  const double prior_weight = kind == FrameKind::kUntracked
                                  ? options.untracked_prior_weight
                                  : options.prior_weight;
  if (prior_weight > 0.0) {
    const double sqrt_weight = std::sqrt(prior_weight * points_per_knot);
    for (int k = 0; k < config.num_knots; ++k) {
      blocks.AddResidual(
          PriorResidual::Create(sqrt_weight, knot_scales, prior.knots[k]),
          nullptr, false, {k});
    }
    blocks.AddResidual(
        PriorResidual::Create(
            std::sqrt(prior_weight * points.size()),
            FunctionScales(*model, HeldEntries(config, kind, kGlobalsBlock)),
            prior.globals),
        nullptr, false, {kGlobalsBlock});
  }

  SolverOptions solver = options.solver;
  // The groups' threads are PrecomputedGroups'; Ceres' own would only copy
  // the results, and waking them cost more than that at a few thousand
  // points.
  if (precomputed) solver.num_threads = 1;
  if (solver.kind == SolverKind::kIntegrator) {
    AddDampingScales(problem, blocks, options.damping_groups, model, &solver);
  }
  if (solver.on_step) {
    solver.on_step = [&blocks,
                      observe = solver.on_step](const SolverTracePoint& point) {
      blocks.Store();
      observe(point);
    };
  }
  SolverReport report = SolveProblem(&problem, solver);
  blocks.Store();
  return report;
}

}  // namespace pfdm
