#include "pfdm/fit/fitter.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>

#include "ceres/ceres.h"
#include "pfdm/fit/data_cost.h"
#include "pfdm/fit/free_entries.h"
#include "pfdm/fit/point_group_residual.h"
#include "pfdm/fit/point_residual.h"
#include "pfdm/fit/regularizer.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr int kReferenceHeld[] = {kA3, kTau, kB0, kB1, kB2, kB3};
constexpr int kGlobalsBlock = -1;
// Weight of the axis gauge per sqrt(point): enough to hold the ring
// centres' mean and trend within 1e-3 mm, no more, since a stiffer penalty
// slows the dynamics solvers (the forward Euler step shrinks with the
// largest eigenvalue) for nothing.
constexpr double kGaugeWeight = 1e1;
// Points per grouped residual block: enough to amortize Ceres' per-block
// work, few enough to leave blocks for every thread.
constexpr size_t kPointsPerGroup = 512;

bool Contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

// Entries of a parameter block (the globals, or knot `block`) that the gauge
// and the configuration hold.  Frame 0 is the reference configuration: no
// twist or bending by definition; a3 is held (at the value initialization
// gave, with a0 spanning the data: see SpanAxialExtent), since a surface
// seen only through distances fixes the meridian's shape but not how u runs
// along it; its axis is the least-squares line of the ring centres
// (AxisGaugeResidual), which leaves the pose to carry the rigid motion.
// With offsets constant in u they are simply held at zero.  A later frame
// with no tracked point holds tau: without material points a turn of a
// ring about the axis is invisible, and the fit would only drift.
enum class FrameKind { kReference, kTracked, kUntracked };

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
      hold = hold || ((f == kE1o || f == kE2o) && block == kGlobalsBlock);
    }
    if (kind == FrameKind::kUntracked) hold = hold || f == kTau;
    if (hold) held.push_back(f);
  }
  return held;
}

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
  for (int f : held) scales[f] = 0.0;
  return scales;
}

// The frame's parameter blocks: the pose as it is, and the globals and each
// knot as their free entries, or whole and constant when none is free.
class FrameBlocks {
 public:
  FrameBlocks(FrameKind kind, Model* model, ceres::Problem* problem)
      : model_(model), problem_(problem) {
    ModelState& state = model->state;
    problem->AddParameterBlock(state.center.data(), 3);
    problem->AddParameterBlock(state.quaternion.data(), 4,
                               new ceres::QuaternionManifold);
    if (kind != FrameKind::kReference) {
      problem->SetParameterBlockConstant(state.center.data());
      problem->SetParameterBlockConstant(state.quaternion.data());
    }
    Add(state.globals.data(), HeldEntries(model->config, kind, kGlobalsBlock));
    for (int k = 0; k < model->config.num_knots; ++k) {
      Add(state.knots[k].data(), HeldEntries(model->config, kind, k));
    }
  }

  // The free entries of a block (kGlobalsBlock or a knot index); null when
  // the block is constant.
  const FreeEntries* entries(int block) const {
    return blocks_[block + 1].entries.get();
  }

  // Adds `cost` over the pose (when with_pose) and then the listed blocks,
  // each as the problem holds it.  A cost over whole blocks is wrapped in
  // FreeEntriesCost; one that takes the blocks as they are says so.
  enum class Takes { kWholeBlocks, kProblemBlocks };
  void AddResidual(ceres::CostFunction* cost, ceres::LossFunction* loss,
                   bool with_pose, const std::vector<int>& blocks,
                   Takes takes = Takes::kWholeBlocks) {
    std::vector<double*> parameters;
    std::vector<const FreeEntries*> entries;
    bool compact = false;
    if (with_pose) {
      parameters = {model_->state.center.data(),
                    model_->state.quaternion.data()};
      entries = {nullptr, nullptr};
    }
    for (int b : blocks) {
      const Block& block = blocks_[b + 1];
      parameters.push_back(block.parameters);
      entries.push_back(block.entries.get());
      compact = compact || block.entries != nullptr;
    }
    if (compact && takes == Takes::kWholeBlocks) {
      cost = new FreeEntriesCost(cost, std::move(entries));
    }
    problem_->AddResidualBlock(cost, loss, parameters);
  }

  // Calls f(parameter block, its free functions) for each free block.
  template <typename F>
  void ForEachFree(F f) const {
    for (const Block& block : blocks_) {
      if (block.entries) f(block.parameters, block.entries->free());
    }
  }

  // Copies the free entries into the model state.
  void Store() const {
    for (const Block& block : blocks_) {
      if (block.entries) block.entries->Store();
    }
  }

 private:
  struct Block {
    double* parameters = nullptr;
    std::unique_ptr<FreeEntries> entries;  // Null when the block is constant.
  };

  void Add(double* values, const std::vector<int>& held) {
    Block block;
    std::vector<int> free;
    for (int f = 0; f < kNumFunctions; ++f) {
      if (!Contains(held, f)) free.push_back(f);
    }
    if (free.empty()) {
      block.parameters = values;
      problem_->AddParameterBlock(values, kNumFunctions);
      problem_->SetParameterBlockConstant(values);
      blocks_.push_back(std::move(block));
      return;
    }
    block.entries = std::make_unique<FreeEntries>(values, std::move(free));
    block.parameters = block.entries->parameters();
    problem_->AddParameterBlock(block.parameters, block.entries->size());
    auto bound = [&](int f, double lower, double upper) {
      const int index = block.entries->IndexOf(f);
      if (index < 0) return;
      problem_->SetParameterLowerBound(block.parameters, index, lower);
      problem_->SetParameterUpperBound(block.parameters, index, upper);
    };
    for (int f : {kA1, kA2, kA3}) bound(f, 1e-3, 1.0);
    for (int f : {kEps1, kEps2}) bound(f, 0.1, 4.0);
    blocks_.push_back(std::move(block));
  }

  Model* model_;
  ceres::Problem* problem_;
  std::vector<Block> blocks_;  // The globals, then the knots.
};

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

// Keeps the model state at log-spaced iterations of a frame's path, and
// the last one, which is where the frame ends.
class TrajectoryRecorder {
 public:
  TrajectoryRecorder(int per_decade, const Model* model,
                     std::vector<TrajectoryPoint>* trajectory)
      : ratio_(per_decade > 0 ? std::pow(10.0, 1.0 / per_decade) : 0.0),
        model_(model),
        trajectory_(trajectory) {}

  void Step(int iteration, double pseudo_time) {
    latest_ = {iteration, pseudo_time, model_->state};
    if (iteration + 1.0 < next_) return;
    trajectory_->push_back(latest_);
    next_ = std::max(next_ + 1.0, (iteration + 1.0) * ratio_);
  }
  void Finish() {
    if (ratio_ > 0.0 && (trajectory_->empty() ||
                         trajectory_->back().iteration != latest_.iteration)) {
      trajectory_->push_back(latest_);
    }
  }

 private:
  double ratio_;
  const Model* model_;
  std::vector<TrajectoryPoint>* trajectory_;
  TrajectoryPoint latest_;
  double next_ = 0.0;
};

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

// One solve of a frame for fixed material points.
// Points listed in `sliding` get the point-to-plane residual, except where
// they lie past the base rim: there the plane says nothing about how far,
// so they pull with the whole distance.  rim_height, when given, is where
// the base rim must sit (RimResidual).
SolverReport SolveFrame(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<MaterialPoint>& material,
                        const std::vector<bool>& sliding,
                        std::optional<double> rim_height, FrameKind kind,
                        const ModelState& prior, const FitOptions& options,
                        Model* model) {
  const ModelConfig& config = model->config;
  const KnotGrid grid = config.Grid();
  ceres::Problem problem;
  FrameBlocks blocks(kind, model, &problem);
  const bool reference = kind == FrameKind::kReference;

  ceres::LossFunction* loss = MakeLoss(options);
  const FunctionMask free_mask = config.FreeMask();
  const bool unit_exponents = model->UnitExponents();
  // Analytic points go into PointGroupResidual blocks, which take the
  // problem's blocks as they are: many points between the same two knots,
  // or one each when every point carries its own robust loss.
  const bool analytic = options.jacobian == JacobianKind::kAnalytic;
  const size_t group_size = loss == nullptr ? kPointsPerGroup : 1;
  std::vector<std::vector<PointSample>> groups(config.num_knots - 1);
  auto add_group = [&](int k0) {
    const std::array<const FreeEntries*, 3> entries = {
        blocks.entries(kGlobalsBlock), blocks.entries(k0),
        blocks.entries(k0 + 1)};
    const std::array<bool, 5> varied = {
        reference, reference, entries[0] != nullptr, entries[1] != nullptr,
        entries[2] != nullptr};
    blocks.AddResidual(new PointGroupResidual(std::move(groups[k0]), free_mask,
                                              unit_exponents, entries, varied),
                       loss, true, {kGlobalsBlock, k0, k0 + 1},
                       FrameBlocks::Takes::kProblemBlocks);
    groups[k0].clear();
  };
  for (size_t i = 0; i < points.size(); ++i) {
    const KnotSpan span = grid.Span(material[i].u);
    const double u = material[i].u, v = material[i].v;
    const bool plane = sliding[i] && u < config.u_max;
    if (analytic) {
      groups[span.k0].push_back(
          plane ? PointSample(points[i], u, v, span.weight,
                              SurfaceNormal(*model, u, v))
                : PointSample(points[i], u, v, span.weight));
      if (groups[span.k0].size() == group_size) add_group(span.k0);
      continue;
    }
    ceres::CostFunction* cost =
        plane ? MakeSurfaceCost(points[i], u, v, span.weight, free_mask,
                                unit_exponents, SurfaceNormal(*model, u, v),
                                options.jacobian)
              : MakePointCost(points[i], u, v, span.weight, free_mask,
                              unit_exponents, options.jacobian);
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
    blocks.AddResidual(
        RimResidual::Create(std::sqrt(points_per_knot), std::sin(config.u_max),
                            *rim_height, free_mask),
        nullptr, false, {kGlobalsBlock, config.num_knots - 1});
  }
  if (reference && config.modes[kE1o] == FunctionMode::kFree) {
    std::vector<int> knots;
    for (int k = 0; k < config.num_knots; ++k) knots.push_back(k);
    blocks.AddResidual(
        new AxisGaugeResidual(config.num_knots,
                              kGaugeWeight * std::sqrt(points.size())),
        nullptr, false, knots);
  }
  if (options.prior_weight > 0.0) {
    const double sqrt_weight =
        std::sqrt(options.prior_weight * points_per_knot);
    for (int k = 0; k < config.num_knots; ++k) {
      blocks.AddResidual(
          PriorResidual::Create(sqrt_weight, knot_scales, prior.knots[k]),
          nullptr, false, {k});
    }
    blocks.AddResidual(
        PriorResidual::Create(
            std::sqrt(options.prior_weight * points.size()),
            FunctionScales(*model, HeldEntries(config, kind, kGlobalsBlock)),
            prior.globals),
        nullptr, false, {kGlobalsBlock});
  }

  SolverOptions solver = options.solver;
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

std::vector<Eigen::Vector3d> Positions(const Frame& frame) {
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(frame.points.size());
  for (const DataPoint& p : frame.points) positions.push_back(p.position);
  return positions;
}

// Fills material[i] for the listed points with their closest material points
// and returns how far (mm) the farthest one moved on the model.
double UpdateClosest(const Model& model,
                     const std::vector<Eigen::Vector3d>& points,
                     const std::vector<size_t>& which,
                     std::vector<MaterialPoint>* material) {
  std::vector<Eigen::Vector3d> subset;
  for (size_t i : which) subset.push_back(points[i]);
  const std::vector<MaterialPoint> closest =
      ClosestMaterialPoints(model, subset);
  double moved = 0.0;
  for (size_t j = 0; j < which.size(); ++j) {
    MaterialPoint& old = (*material)[which[j]];
    moved = std::max(moved, (model.WorldPoint(closest[j].u, closest[j].v) -
                             model.WorldPoint(old.u, old.v))
                                .norm());
    old = closest[j];
  }
  return moved;
}

void Summarize(const Model& model, const std::vector<Eigen::Vector3d>& points,
               FrameFit* fit) {
  double sum_squared = 0.0, sum = 0.0, max = 0.0;
  fit->residuals.clear();
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d r =
        model.WorldPoint(fit->material[i].u, fit->material[i].v) - points[i];
    fit->residuals.push_back(r);
    sum_squared += r.squaredNorm();
    sum += r.norm();
    max = std::max(max, r.norm());
  }
  fit->rms_mm = std::sqrt(sum_squared / points.size());
  fit->mean_distance_mm = sum / points.size();
  fit->max_distance_mm = max;
  fit->state = model.state;
}

// Height along the model axis of the highest data point that is not an
// outlier: with a robust loss, points farther than three loss scales from
// the surface do not count.  NaN when none counts.
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

// Sets a0 so that the model, a3 held, reaches from its fitted apex to the
// highest data point along its axis (the base rim), keeping the apex, the
// radii in mm and the orientation where they are.
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

}  // namespace

SequenceFit FitSequence(const PointSequence& sequence,
                        const ModelConfig& config, const FitOptions& options) {
  if (sequence.frames.empty()) {
    throw InputError(sequence.source + ": no frames");
  }
  std::unordered_map<std::int64_t, int> frames_per_id;
  for (const Frame& frame : sequence.frames) {
    if (static_cast<int>(frame.points.size()) < options.min_points) {
      throw InputError(sequence.source + ": frame " +
                       std::to_string(frame.index) + ": only " +
                       std::to_string(frame.points.size()) +
                       " points, at least " +
                       std::to_string(options.min_points) + " needed");
    }
    for (const DataPoint& p : frame.points) ++frames_per_id[p.id];
  }

  SequenceFit result;
  result.config = config;
  Model model =
      InitializeModel(config, Positions(sequence.frames[0]), options.hint);
  ModelState prior = model.state;
  std::unordered_map<std::int64_t, MaterialPoint> tracked_material;

  for (const Frame& frame : sequence.frames) {
    const auto start = std::chrono::steady_clock::now();
    const bool reference = frame.index == sequence.frames[0].index;
    const std::vector<Eigen::Vector3d> points = Positions(frame);
    FrameFit fit;
    fit.frame = frame.index;
    fit.material.resize(points.size());
    std::vector<size_t> unknown;
    for (size_t i = 0; i < points.size(); ++i) {
      auto it = tracked_material.find(frame.points[i].id);
      if (it != tracked_material.end()) {
        fit.material[i] = it->second;
      } else {
        unknown.push_back(i);
      }
    }
    UpdateClosest(model, points, unknown, &fit.material);
    std::vector<bool> sliding(points.size(), false);
    for (size_t i : unknown) sliding[i] = true;

    const FrameKind kind = reference ? FrameKind::kReference
                           : unknown.size() == points.size()
                               ? FrameKind::kUntracked
                               : FrameKind::kTracked;
    SolverReport report;
    TrajectoryRecorder recorder(options.trajectory_per_decade, &model,
                                &fit.trajectory);
    for (int round = 0; round < options.max_correspondence_rounds; ++round) {
      std::optional<double> rim_height;
      if (!reference && !unknown.empty()) {
        const double top = TopHeight(points, options, model);
        if (std::isfinite(top)) rim_height = top;
      }
      const SolverTracePoint last =
          fit.trace.empty() ? SolverTracePoint{-1} : fit.trace.back();
      FitOptions round_options = options;
      if (options.trajectory_per_decade > 0) {
        round_options.solver.on_step = [&recorder,
                                        last](const SolverTracePoint& point) {
          recorder.Step(last.iteration + 1 + point.iteration,
                        last.pseudo_time + point.pseudo_time);
        };
      }
      report = SolveFrame(points, fit.material, sliding, rim_height, kind,
                          prior, round_options, &model);
      fit.iterations += report.iterations;
      fit.residual_evaluations += report.residual_evaluations;
      fit.jacobian_evaluations += report.jacobian_evaluations;
      fit.jacobian_seconds += report.jacobian_seconds;
      fit.linear_solver_seconds += report.linear_solver_seconds;
      fit.minimizer_seconds += report.minimizer_seconds;
      ++fit.correspondence_rounds;
      for (SolverTracePoint point : report.trace) {
        point.iteration += last.iteration + 1;
        point.pseudo_time += last.pseudo_time;
        point.wall_seconds += last.wall_seconds;
        fit.trace.push_back(point);
      }
      if (!report.usable) {
        throw InputError(sequence.source + ": frame " +
                         std::to_string(frame.index) +
                         ": solver failed: " + report.message);
      }
      if (unknown.empty()) break;
      if (reference) SpanAxialExtent(points, options, &model);
      const double moved = UpdateClosest(model, points, unknown, &fit.material);
      if (moved < options.correspondence_tolerance_mm) break;
    }
    recorder.Finish();
    fit.termination = report.termination;
    for (size_t i : unknown) {
      if (frames_per_id[frame.points[i].id] > 1) {
        tracked_material[frame.points[i].id] = fit.material[i];
      }
    }
    // The recorded path goes into the frame's final gauge with the frame.
    const BendingShift turns = model.CanonicalizeBending();
    if (turns != BendingShift{0.0, 0.0}) {
      for (TrajectoryPoint& point : fit.trajectory) {
        Model recorded{config, point.state};
        recorded.ShiftBending(turns);
        point.state = recorded.state;
      }
    }
    Summarize(model, points, &fit);
    fit.solve_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    prior = model.state;
    result.frames.push_back(std::move(fit));
  }
  return result;
}

}  // namespace pfdm
