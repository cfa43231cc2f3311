#include "pfdm/fit/fitter.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>

#include "Eigen/Dense"
#include "pfdm/fit/frame_problem.h"
#include "pfdm/fit/gauge.h"
#include "pfdm/fit/local_fit.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

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
                     const std::vector<size_t>& which, int num_threads,
                     std::vector<MaterialPoint>* material) {
  std::vector<Eigen::Vector3d> subset;
  for (size_t i : which) subset.push_back(points[i]);
  CorrespondenceOptions correspondence;
  correspondence.num_threads = num_threads;
  const std::vector<MaterialPoint> closest =
      ClosestMaterialPoints(model, subset, correspondence);
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
// Sets a0 so that the model, a3 held, reaches from its fitted apex to the
// highest data point along its axis (the base rim), keeping the apex, the
// radii in mm and the orientation where they are.
// A surface is fitted to points that span space; identical, collinear or
// coplanar points once reached Ceres as NaN (a CHECK dump) or "fitted" with
// exit 0.  Spreads are the principal standard deviations, mm.
void CheckSpansSpace(const std::string& source, const Frame& frame) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const DataPoint& p : frame.points) mean += p.position;
  mean /= static_cast<double>(frame.points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const DataPoint& p : frame.points) {
    covariance += (p.position - mean) * (p.position - mean).transpose();
  }
  covariance /= static_cast<double>(frame.points.size());
  const Eigen::Vector3d spread =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance)
          .eigenvalues()
          .cwiseMax(0.0)
          .cwiseSqrt();  // Ascending.
  const char* what = nullptr;
  if (!(spread[2] > 1e-6)) {
    what = "all at one place";
  } else if (spread[1] < 1e-3 * spread[2]) {
    what = "on a line";
  } else if (spread[0] < 1e-3 * spread[2]) {
    what = "in a plane";
  }
  if (what != nullptr) {
    throw InputError(source + ": frame " + std::to_string(frame.index) +
                     ": the points lie " + what +
                     "; a surface needs points that span space");
  }
}

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
  return finite(state.local.values);
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
    CheckSpansSpace(sequence.source, frame);
  }

  SequenceFit result;
  result.config = config;
  Model model =
      InitializeModel(config, Positions(sequence.frames[0]), options.hint);
  ModelState prior = model.state;
  // Frame 0's pose, which later frames may tilt and move but not spin.
  std::array<double, 4> reference_quaternion = model.state.quaternion;
  ModelState reference_state = model.state;
  std::unordered_map<std::int64_t, MaterialPoint> tracked_material;

  for (const Frame& frame : sequence.frames) {
    const auto start = std::chrono::steady_clock::now();
    const bool reference = frame.index == sequence.frames[0].index;
    const std::vector<Eigen::Vector3d> points = Positions(frame);
    // The global rounds fit the global model alone; the local field comes
    // after them (FitLocalField).
    model.state.local = LocalField();
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
    auto closest_start = std::chrono::steady_clock::now();
    UpdateClosest(model, points, unknown, options.solver.num_threads,
                  &fit.material);
    fit.correspondence_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                      closest_start)
            .count();
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
      report =
          SolveFrame(points, fit.material, sliding, rim_height, kind,
                     kind == FrameKind::kUntracked ? reference_state : prior,
                     reference_quaternion, round_options, &model);
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
      closest_start = std::chrono::steady_clock::now();
      const double moved = UpdateClosest(
          model, points, unknown, options.solver.num_threads, &fit.material);
      fit.correspondence_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                        closest_start)
              .count();
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
    if (options.local.enabled) {
      // Points seen in one frame only (contours) pull along the normal and
      // then find their closest points on the whole model, as they did on
      // the global one: the field moves the surface along itself too.
      // Tracked points keep the global fit's material point (saved above)
      // and pull with the whole vector on every frame, frame 0 included.
      std::vector<size_t> contour;
      std::vector<bool> local_sliding(points.size(), false);
      for (size_t i : unknown) {
        if (frames_per_id[frame.points[i].id] > 1) continue;
        contour.push_back(i);
        local_sliding[i] = true;
      }
      const auto local_start = std::chrono::steady_clock::now();
      for (int round = 0; round < options.max_correspondence_rounds; ++round) {
        const SolverReport local =
            FitLocalField(points, fit.material, local_sliding, options, &model);
        fit.local_iterations += local.iterations;
        if (!local.usable) {
          throw InputError(
              sequence.source + ": frame " + std::to_string(frame.index) +
              ": local deformations: solver failed: " + local.message);
        }
        if (contour.empty() ||
            UpdateClosest(model, points, contour, options.solver.num_threads,
                          &fit.material) <
                options.correspondence_tolerance_mm) {
          break;
        }
      }
      fit.local_seconds = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - local_start)
                              .count();
    }
    Summarize(model, points, &fit);
    // Never a silent absurd fit: an infinite RMS once printed CONVERGENCE.
    if (!std::isfinite(fit.rms_mm) || !std::isfinite(fit.max_distance_mm) ||
        !StateFinite(model.state)) {
      throw InputError(sequence.source + ": frame " +
                       std::to_string(frame.index) +
                       ": the fit diverged (its error is not finite)");
    }
    fit.solve_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    prior = model.state;
    if (reference) {
      reference_quaternion = model.state.quaternion;
      reference_state = model.state;
    }
    result.frames.push_back(std::move(fit));
  }
  return result;
}

}  // namespace pfdm
