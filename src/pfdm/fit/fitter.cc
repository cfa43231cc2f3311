#include "pfdm/fit/fitter.h"

#include <chrono>
#include <cmath>
#include <cstdio>
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

// The listed points' material points.
std::vector<MaterialPoint> Listed(const std::vector<MaterialPoint>& material,
                                  const std::vector<size_t>& which) {
  std::vector<MaterialPoint> listed;
  listed.reserve(which.size());
  for (size_t i : which) listed.push_back(material[i]);
  return listed;
}

// Fills material[i] for the listed points with their closest material
// points, normals[i] with the normals they pull along (zero where they do
// not: PullsAlongNormal) and found[j] with their model points, in the
// listed order.  In a solid, a point is sought on its surface: layer_w[i]
// for a contour of one wall, or, when depths are assigned (frame 0's tags),
// QuantileDepths' w.
void UpdateClosest(const Model& model,
                   const std::vector<Eigen::Vector3d>& points,
                   const std::vector<size_t>& which, int num_threads,
                   const std::vector<double>& layer_w,
                   const std::vector<bool>& assign_depth, bool warm,
                   std::vector<MaterialPoint>* material,
                   std::vector<Eigen::Vector3d>* normals,
                   std::vector<Eigen::Vector3d>* found) {
  std::vector<Eigen::Vector3d> subset;
  for (size_t i : which) subset.push_back(points[i]);
  CorrespondenceOptions correspondence;
  correspondence.num_threads = num_threads;
  if (warm) {
    for (size_t i : which) correspondence.hints.push_back((*material)[i]);
  }
  std::vector<Eigen::Vector3d> found_normals;
  std::vector<MaterialPoint> closest = ClosestMaterialPoints(
      model, subset, correspondence, found, &found_normals);
  if (model.config.Solid()) {
    std::vector<size_t> tags;
    std::vector<Eigen::Vector3d> tag_points;
    std::vector<MaterialPoint> tag_material;
    std::vector<double> tag_u;
    correspondence.surfaces.assign(which.size(), 0.0);
    for (size_t j = 0; j < which.size(); ++j) {
      correspondence.surfaces[j] = layer_w[which[j]];
      if (!assign_depth[which[j]]) continue;
      tags.push_back(j);
      tag_points.push_back(subset[j]);
      tag_material.push_back(closest[j]);
      tag_u.push_back(closest[j].u);
    }
    const std::vector<double> depths = QuantileDepths(
        tag_u, MidwallDistances(model, tag_points, tag_material));
    for (size_t t = 0; t < tags.size(); ++t) {
      correspondence.surfaces[tags[t]] = depths[t];
    }
    // Off the mid-wall, the closest point of the point's own surface.
    std::vector<size_t> off;
    CorrespondenceOptions on_surface = correspondence;
    on_surface.surfaces.clear();
    std::vector<Eigen::Vector3d> off_points;
    on_surface.hints.clear();
    for (size_t j = 0; j < which.size(); ++j) {
      if (correspondence.surfaces[j] == 0.0) continue;
      off.push_back(j);
      off_points.push_back(subset[j]);
      on_surface.surfaces.push_back(correspondence.surfaces[j]);
      if (warm) on_surface.hints.push_back((*material)[which[j]]);
    }
    std::vector<Eigen::Vector3d> found_off, normals_off;
    const std::vector<MaterialPoint> refined = ClosestMaterialPoints(
        model, off_points, on_surface, &found_off, &normals_off);
    for (size_t k = 0; k < off.size(); ++k) {
      closest[off[k]] = refined[k];
      (*found)[off[k]] = found_off[k];
      found_normals[off[k]] = normals_off[k];
    }
  }
  for (size_t j = 0; j < which.size(); ++j) {
    (*material)[which[j]] = closest[j];
    (*normals)[which[j]] = PullsAlongNormal(model.config, closest[j])
                               ? found_normals[j]
                               : Eigen::Vector3d::Zero();
  }
}

// The largest distance (mm) between paired points.
double MaxDistance(const std::vector<Eigen::Vector3d>& a,
                   const std::vector<Eigen::Vector3d>& b) {
  double distance = 0.0;
  for (size_t j = 0; j < a.size(); ++j) {
    distance = std::max(distance, (a[j] - b[j]).norm());
  }
  return distance;
}

void AddSolverCounts(const SolverReport& report, FrameFit* fit) {
  fit->iterations += report.iterations;
  fit->residual_evaluations += report.residual_evaluations;
  fit->jacobian_evaluations += report.jacobian_evaluations;
  fit->evaluation_seconds += report.evaluation_seconds;
  fit->linear_solver_seconds += report.linear_solver_seconds;
  fit->minimizer_seconds += report.minimizer_seconds;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// The local field's contour rounds end when one lowers the field's cost by
// less than this share: on biv-me's contours the cost falls 5 % in the
// second round, then wanders within a percent for as many rounds as
// allowed, points sliding back and forth along the surface by a millimetre
// or two, never settling to the correspondence tolerance.
constexpr double kMinLocalRoundGain = 0.01;

// Frame 0 of at least twice this many points starts with a round on this
// many of them (FitSequence).
constexpr size_t kCoarsePoints = 4096;

// A correspondence round's search is skipped as confirmation when the one
// before moved no point by this many tolerances and the solve since moved
// the surface little (FitSequence).
constexpr double kConfirmBelow = 10.0;

// Solves of a tracked frame of a solid, each after its tags were ranked:
// the second changes thickening by under 0.1 point on the LV phantom, a
// third by nothing visible, while each costs a whole solve.
constexpr int kRerankRounds = 2;

// Sets the listed points' w to their QuantileDepths on `model` and returns
// how far (mm) the farthest one's model point moved.  Why each frame ranks
// its tags afresh rather than keeping frame 0's w: a w read from noisy
// distances regresses every later frame's thickness toward zero (errors in
// the regressor), by the noise's share of the depths' variance, while frame
// 0's own h comes out inflated by as much; ranked in every frame, h is
// biased alike in all of them and the thickening (a ratio) is not.  A tag's
// place in the order across the wall is material; its rank changes only by
// noise.
double RerankDepths(const Model& model,
                    const std::vector<Eigen::Vector3d>& points,
                    const std::vector<size_t>& which,
                    std::vector<MaterialPoint>* material) {
  std::vector<Eigen::Vector3d> subset;
  std::vector<MaterialPoint> subset_material;
  std::vector<double> u;
  for (size_t i : which) {
    subset.push_back(points[i]);
    subset_material.push_back((*material)[i]);
    u.push_back((*material)[i].u);
  }
  const std::vector<double> depths =
      QuantileDepths(u, MidwallDistances(model, subset, subset_material));
  double moved = 0.0;
  for (size_t j = 0; j < which.size(); ++j) {
    MaterialPoint& m = (*material)[which[j]];
    moved = std::max(moved, (model.WorldPoint(m.u, m.v, depths[j]) -
                             model.WorldPoint(m.u, m.v, m.w))
                                .norm());
    m.w = depths[j];
  }
  return moved;
}

void Summarize(const Model& model, const std::vector<Eigen::Vector3d>& points,
               FrameFit* fit);

// A solid's tags were ranked across the wall in every frame, which widens
// each frame's h by their noise, a thin wall's more (DeconvolvedThickness):
// measures the noise on the tracked frames and takes it out of every
// frame's h, then summarizes the frames again.
void TakeOutTagNoise(const PointSequence& sequence,
                     const std::unordered_map<std::int64_t, int>& frames_per_id,
                     SequenceFit* result) {
  double sum_squared = 0.0;
  int frames = 0;
  for (size_t t = 1; t < result->frames.size(); ++t) {
    const FrameFit& frame = result->frames[t];
    // Tracked tags only: a contour point's closest point leaves it no
    // residual along the wall.
    std::vector<size_t> tags;
    for (size_t i = 0; i < frame.material.size(); ++i) {
      if (frames_per_id.at(sequence.frames[t].points[i].id) > 1) {
        tags.push_back(i);
      }
    }
    if (tags.empty()) continue;
    const double sigma =
        TangentialNoiseMm(result->ModelAt(static_cast<int>(t)), frame.residuals,
                          frame.material, tags);
    sum_squared += sigma * sigma;
    ++frames;
  }
  if (frames == 0) return;
  result->tag_noise_mm = std::sqrt(sum_squared / frames);
  for (size_t t = 0; t < result->frames.size(); ++t) {
    FrameFit& frame = result->frames[t];
    Model model{result->config, frame.state};
    model.state.globals[kH] =
        DeconvolvedThickness(model.state.globals[kH], result->tag_noise_mm);
    for (FunctionValues& knot : model.state.knots) {
      knot[kH] = DeconvolvedThickness(knot[kH], result->tag_noise_mm);
    }
    Summarize(model, Positions(sequence.frames[t]), &frame);
  }
}

void Summarize(const Model& model, const std::vector<Eigen::Vector3d>& points,
               FrameFit* fit) {
  double sum_squared = 0.0, sum = 0.0, max = 0.0;
  fit->residuals.clear();
  const std::vector<Eigen::Vector3d> model_points =
      WorldPoints(model, fit->material);
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d r = model_points[i] - points[i];
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

// How a frame's points are sought in a solid: a contour's wall, +-1; 0
// for everything else (tags get their depth from QuantileDepths).
std::vector<double> LayerDepths(const Frame& frame) {
  std::vector<double> w;
  for (const DataPoint& p : frame.points) {
    w.push_back(p.layer == WallLayer::kEndocardium  ? -1.0
                : p.layer == WallLayer::kEpicardium ? 1.0
                                                    : 0.0);
  }
  return w;
}

// Which walls a frame's contours name.
struct WallsSeen {
  bool endo = false;
  bool epi = false;
};

WallsSeen WallsIn(const Frame& frame) {
  WallsSeen seen;
  for (const DataPoint& p : frame.points) {
    seen.endo = seen.endo || p.layer == WallLayer::kEndocardium;
    seen.epi = seen.epi || p.layer == WallLayer::kEpicardium;
  }
  return seen;
}

std::string FormatMm(double mm) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", mm);
  return text;
}

}  // namespace

std::string UnsettledNote(const FrameFit& frame) {
  if (frame.unsettled_mm <= 0.0) return "";
  char text[80];
  std::snprintf(text, sizeof(text),
                "; closest points unsettled (%.2f mm in the last search)",
                frame.unsettled_mm);
  return text;
}

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
  // The wall: contours of both walls make a solid from the start; tags
  // through the wall are told from tags on one surface after frame 0's
  // mid-wall fit (below).
  const Frame& first = sequence.frames[0];
  bool has_tags = false;
  for (const DataPoint& p : first.points) {
    has_tags = has_tags || frames_per_id[p.id] > 1;
  }
  const WallsSeen walls = WallsIn(first);
  if (options.wall == WallModel::kMidwall) {
    result.wall_reason = "--wall midwall";
  } else if (walls.endo && walls.epi) {
    model.config.MakeSolid();
    result.wall_reason = "endocardial and epicardial contours";
  } else if (!has_tags) {
    if (options.wall == WallModel::kSolid) {
      throw InputError(sequence.source +
                       ": --wall solid needs tags tracked through the wall "
                       "or contours of both walls (lv-cavity,lv-epi)");
    }
    result.wall_reason = "no tracked tags and no contours of both walls";
  }
  bool wall_decided = !result.wall_reason.empty();
  if (!model.config.Solid() && walls.endo != walls.epi) {
    result.surface =
        walls.endo ? WallLayer::kEndocardium : WallLayer::kEpicardium;
  }
  ModelState prior = model.state;
  // Frame 0's pose, which later frames may tilt and move but not spin.
  std::array<double, 4> reference_quaternion = model.state.quaternion;
  ModelState reference_state = model.state;
  std::unordered_map<std::int64_t, MaterialPoint> tracked_material;

  for (const Frame& frame : sequence.frames) {
    const auto start = std::chrono::steady_clock::now();
    const bool reference = frame.index == sequence.frames[0].index;
    const std::vector<Eigen::Vector3d> points = Positions(frame);
    const std::vector<double> layer_w = LayerDepths(frame);
    // The global rounds fit the global model alone; the local field comes
    // after them (FitLocalField).
    model.state.local = LocalField();
    FrameFit fit;
    fit.frame = frame.index;
    fit.material.resize(points.size());
    std::vector<size_t> unknown;
    // Frame 0's tags, whose depth in a solid comes from their spread.
    std::vector<bool> assign_depth(points.size(), false);
    for (size_t i = 0; i < points.size(); ++i) {
      auto it = tracked_material.find(frame.points[i].id);
      if (it != tracked_material.end()) {
        fit.material[i] = it->second;
      } else {
        unknown.push_back(i);
        assign_depth[i] = reference && frames_per_id[frame.points[i].id] > 1;
      }
    }
    // What the last search found: the unknown points' model points (in
    // their order) on the model it searched, and the normals along which
    // the points pull, current until a solve moves the model.
    std::vector<Eigen::Vector3d> found;
    std::vector<Eigen::Vector3d> normals(points.size(),
                                         Eigen::Vector3d::Zero());
    bool normals_current = true;
    bool found_closest = false;  // Then searches start from the last.
    // Returns how far (mm) the farthest point's model point moved: from
    // `now`, its model point before the search (computed when not given).
    auto update_closest = [&](std::vector<Eigen::Vector3d> now = {}) {
      const auto closest_start = std::chrono::steady_clock::now();
      if (found_closest && now.empty()) {
        now = WorldPoints(model, Listed(fit.material, unknown));
      }
      UpdateClosest(model, points, unknown, options.solver.num_threads, layer_w,
                    assign_depth, found_closest, &fit.material, &normals,
                    &found);
      const double moved = found_closest || unknown.empty()
                               ? MaxDistance(now, found)
                               : std::numeric_limits<double>::infinity();
      found_closest = true;
      normals_current = true;
      fit.correspondence_seconds += SecondsSince(closest_start);
      return moved;
    };
    std::vector<bool> sliding(points.size(), false);
    for (size_t i : unknown) sliding[i] = true;
    if (reference && unknown.size() >= 2 * kCoarsePoints) {
      // Coarse to fine: a first round on every k-th point brings the
      // initialized model to the data at a fraction of a round's cost, and
      // the rounds on all points start from there (one round fewer).
      std::vector<size_t> coarse;
      const size_t stride = unknown.size() / kCoarsePoints;
      for (size_t j = 0; j < unknown.size(); j += stride) {
        coarse.push_back(unknown[j]);
      }
      const auto closest_start = std::chrono::steady_clock::now();
      UpdateClosest(model, points, coarse, options.solver.num_threads, layer_w,
                    assign_depth, false, &fit.material, &normals, &found);
      fit.correspondence_seconds += SecondsSince(closest_start);
      std::vector<Eigen::Vector3d> coarse_points, coarse_normals;
      std::vector<MaterialPoint> coarse_material;
      for (size_t i : coarse) {
        coarse_points.push_back(points[i]);
        coarse_material.push_back(fit.material[i]);
        coarse_normals.push_back(normals[i]);
      }
      FitOptions coarse_options = options;
      coarse_options.solver.on_step = nullptr;  // Not part of the path.
      const SolverReport coarse_report =
          SolveFrame(coarse_points, coarse_material, coarse_normals,
                     std::nullopt, FrameKind::kReference, prior,
                     reference_quaternion, coarse_options, &model);
      AddSolverCounts(coarse_report, &fit);
      SpanAxialExtent(points, options, &model);
    }
    double moved = update_closest();

    const FrameKind kind = reference ? FrameKind::kReference
                           : unknown.size() == points.size()
                               ? FrameKind::kUntracked
                               : FrameKind::kTracked;
    SolverReport report;
    TrajectoryRecorder recorder(options.trajectory_per_decade, &model,
                                &fit.trajectory);
    // A solid's tracked tags keep (u, v) but take their depth from this
    // frame's ranks (RerankDepths).
    std::vector<size_t> tracked_tags;
    for (size_t i = 0; i < points.size(); ++i) {
      if (!reference && tracked_material.count(frame.points[i].id) > 0) {
        tracked_tags.push_back(i);
      }
    }
    const bool rerank_depths = model.config.Solid() && !tracked_tags.empty();
    if (rerank_depths) {
      RerankDepths(model, points, tracked_tags, &fit.material);
    }
    auto solve_rounds = [&]() {
      fit.unsettled_mm = 0.0;
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
        if (!normals_current) {
          normals = SlidingNormals(model, fit.material, sliding);
        }
        report =
            SolveFrame(points, fit.material, normals, rim_height, kind,
                       kind == FrameKind::kUntracked ? reference_state : prior,
                       reference_quaternion, round_options, &model);
        normals_current = false;
        AddSolverCounts(report, &fit);
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
        if (rerank_depths) {
          // Ranks settle in a round or two; later rounds only trade noise
          // between tags (kRerankRounds).
          if (round + 1 >= kRerankRounds ||
              RerankDepths(model, points, tracked_tags, &fit.material) <
                  options.correspondence_tolerance_mm) {
            break;
          }
          continue;
        }
        if (unknown.empty()) break;
        if (reference) SpanAxialExtent(points, options, &model);
        // Near convergence, how far the solve moved the surface under the
        // points bounds how far their closest points can move (about that
        // far, the points being close to a gently curved surface): under
        // half the tolerance, the search that would confirm it is skipped.
        std::vector<Eigen::Vector3d> now;
        if (moved < kConfirmBelow * options.correspondence_tolerance_mm) {
          now = WorldPoints(model, Listed(fit.material, unknown));
          if (MaxDistance(now, found) <
              0.5 * options.correspondence_tolerance_mm) {
            break;
          }
        }
        moved = update_closest(std::move(now));
        if (moved < options.correspondence_tolerance_mm) break;
        if (round + 1 == options.max_correspondence_rounds) {
          fit.unsettled_mm = moved;
        }
      }
    };
    solve_rounds();
    if (reference && !wall_decided) {
      // Tags through the wall, or on one surface?  Their spread about the
      // fitted mid-wall says.
      std::vector<Eigen::Vector3d> tag_points;
      std::vector<MaterialPoint> tag_material;
      std::vector<double> tag_u;
      for (size_t i = 0; i < points.size(); ++i) {
        if (!assign_depth[i]) continue;
        tag_points.push_back(points[i]);
        tag_material.push_back(fit.material[i]);
        tag_u.push_back(fit.material[i].u);
      }
      std::vector<Eigen::Vector3d> midwall_points;
      const std::vector<double> distances =
          MidwallDistances(model, tag_points, tag_material, &midwall_points);
      const double spread = WallSpreadMm(midwall_points, distances);
      result.wall_reason =
          "tags spread " + FormatMm(spread) + " mm across the wall";
      // An unfinished solve leaves tags far from the surface too: only a
      // converged one tells a wall from a fit that stopped early.
      const bool wall_seen = spread >= kMinWallSpreadMm && report.converged;
      if (options.wall == WallModel::kSolid || wall_seen) {
        model.config.MakeSolid();
        const double h = std::max(
            0.0,
            ThicknessFromDepths(distances, QuantileDepths(tag_u, distances)));
        model.state.globals[kH] = h;
        for (FunctionValues& knot : model.state.knots) knot[kH] = h;
        if (options.wall == WallModel::kSolid) {
          result.wall_reason += " (--wall solid)";
        }
        moved = update_closest();
        solve_rounds();
      } else if (!report.converged) {
        result.wall_reason +=
            ", but frame 0's mid-wall solve did not converge: one surface";
      } else {
        result.wall_reason +=
            ": one surface (under " + FormatMm(kMinWallSpreadMm) + " mm)";
      }
      wall_decided = true;
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
        Model recorded{model.config, point.state};
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
      double last_cost = std::numeric_limits<double>::infinity();
      for (int round = 0; round < options.max_correspondence_rounds; ++round) {
        const SolverReport local =
            FitLocalField(points, fit.material, local_sliding, options, &model);
        fit.local_iterations += local.iterations;
        if (!local.usable) {
          throw InputError(
              sequence.source + ": frame " + std::to_string(frame.index) +
              ": local deformations: solver failed: " + local.message);
        }
        const double cost = local.trace.empty() ? 0.0 : local.trace.back().cost;
        const bool stalled = cost > (1.0 - kMinLocalRoundGain) * last_cost;
        last_cost = cost;
        if (contour.empty()) break;
        // Stalled or not, the contours' material points are then the
        // closest on the final model, as their distances are reported.
        const std::vector<Eigen::Vector3d> before =
            WorldPoints(model, Listed(fit.material, contour));
        std::vector<Eigen::Vector3d> contour_found;
        UpdateClosest(model, points, contour, options.solver.num_threads,
                      layer_w, std::vector<bool>(points.size(), false),
                      /*warm=*/true, &fit.material, &normals, &contour_found);
        const double contour_moved = MaxDistance(before, contour_found);
        if (stalled || contour_moved < options.correspondence_tolerance_mm) {
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
  result.config = model.config;
  if (result.config.Solid()) result.surface = WallLayer::kAnywhere;
  if (result.config.Solid() && has_tags) {
    TakeOutTagNoise(sequence, frames_per_id, &result);
  }
  return result;
}

}  // namespace pfdm
