#include "pfdm/fit/stages/start_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "pfdm/fit/stages/cloud_length.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/frame_summary.h"
#include "pfdm/fit/stages/global_rounds.h"
#include "pfdm/fit/stages/initialization.h"
#include "pfdm/fit/stages/parallel_planes.h"
#include "pfdm/fit/stages/trajectory_recorder.h"
#include "pfdm/model/knot_resampling.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Points of frame 0 a candidate is tried on: the choice is between
// directions tens of degrees apart, which a few hundred points tell.
constexpr size_t kChoicePoints = 300;
// Correspondence rounds a candidate is fitted with: enough for a wrong
// axis to turn toward the right one (30-40 degrees on the mid-ventricular
// phantom) or to show its misfit.
constexpr int kChoiceRounds = 5;
// Close calls: candidates whose screened cost is within this factor of the
// best one's (on whole ventricles the principal axis' is 4 times lower
// than the others'; on a mid-ventricular segment's mid-wall tags 2 times),
// at most kFinalists of them, fitted on with kFinalPoints points.
constexpr double kCloseCall = 1.25;
constexpr size_t kFinalists = 3;
constexpr size_t kFinalPoints = 800;
// Knots of a whole ventricle's screened candidates: their linear solves are
// most of the start's time and shrink with the cube of the knots; the
// principal axis still wins by 4 times the others' cost (the 2,000-tag
// phantom's start 128-156 -> 68-74 ms, the axis as before).  A squat cloud's
// candidates, close calls a few degrees apart, keep the model's knots:
// with 5, of four mid-ventricular cases the fitted axis came 0.1-0.2
// degrees nearer the truth in two, as near in one and 0.35 farther in the
// cylinder's tags through the wall (6 seeds each).  A finalist goes on from its
// screened model sampled at the model's knots (ResampleKnots): the same
// functions, 5 knots uniform in sin u being among 17's.
constexpr int kChoiceKnots = 5;

// At most `most` of frame 0's points, evenly spread over their order, with
// ids of their own.
std::vector<DataPoint> ChoicePoints(const Frame& first, size_t most) {
  std::vector<DataPoint> points;
  const size_t n = first.points.size();
  const size_t kept = std::min(n, most);
  for (size_t k = 0; k < kept; ++k) {
    DataPoint p = first.points[k * n / kept];
    p.id = static_cast<std::int64_t>(k);
    points.push_back(p);
  }
  return points;
}

std::string PlanesSource(int count) {
  return "normal of " + std::to_string(count) + " parallel planes";
}

// The candidate (its index in *winner) whose fit of frame 0 costs least:
// each screened on kChoicePoints with kChoiceRounds; where others come
// within kCloseCall of the best (tags through the wall: their 3 mm spread
// across it is most of every candidate's cost), the kFinalists best fitted
// on from where they got, on kFinalPoints to the rounds' end, and the best
// of those.
CandidateFit BestCandidate(const Frame& first, const ModelConfig& config,
                           const std::vector<Eigen::Vector3d>& candidates,
                           const FitOptions& options, const std::string& source,
                           size_t* winner) {
  const std::vector<Eigen::Vector3d> points = Positions(first);
  const std::vector<DataPoint> screen = ChoicePoints(first, kChoicePoints);
  ModelConfig choice_config = config;
  if (LengthOf(points).Elongated()) {
    choice_config.num_knots = std::min(config.num_knots, kChoiceKnots);
  }
  std::vector<CandidateFit> fits;
  for (const Eigen::Vector3d& candidate : candidates) {
    fits.push_back(FitCandidate(
        screen, InitializeModelAlong(choice_config, points, candidate), options,
        source, kChoiceRounds));
  }
  std::vector<size_t> order(fits.size());
  std::iota(order.begin(), order.end(), size_t{0});
  // Stable: the first stands when every candidate's fit fails.
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return fits[a].cost < fits[b].cost;
  });
  *winner = order[0];
  const double screened = fits[order[0]].cost;
  if (!(fits[order[1]].cost < kCloseCall * screened)) return fits[*winner];
  const std::vector<DataPoint> final_points = ChoicePoints(first, kFinalPoints);
  double lowest = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < std::min(kFinalists, order.size()); ++k) {
    const size_t i = order[k];
    if (!(fits[i].cost < kCloseCall * screened)) break;
    fits[i] = FitCandidate(final_points, ResampleKnots(fits[i].model, config),
                           options, source, options.max_correspondence_rounds);
    if (fits[i].cost < lowest) lowest = fits[i].cost, *winner = i;
  }
  return fits[*winner];
}

}  // namespace

std::vector<Eigen::Vector3d> CandidateAxes(
    const std::vector<Eigen::Vector3d>& points) {
  const Eigen::Matrix3d axes = PrincipalAxes(points);
  std::vector<Eigen::Vector3d> candidates{axes.col(2), axes.col(1),
                                          axes.col(0)};
  if (!LengthOf(points).Elongated()) {
    for (int i = 0; i < 3; ++i) {
      for (int j = i + 1; j < 3; ++j) {
        candidates.push_back((axes.col(i) + axes.col(j)).normalized());
        candidates.push_back((axes.col(i) - axes.col(j)).normalized());
      }
    }
  }
  return candidates;
}

CandidateFit FitCandidate(const std::vector<DataPoint>& points,
                          const Model& model, const FitOptions& options,
                          const std::string& source, int max_rounds) {
  Frame frame;
  frame.points = points;
  FramesPerId once;
  for (const DataPoint& p : points) once[p.id] = 1;
  FrameFit fit;
  const FramePoints frame_points =
      MakeFramePoints(frame, true, once, TrackedMaterial(), &fit.material);
  FitOptions choice = options;
  // The direct solve, whichever the fit uses: the dynamics' steps are
  // about the path (they also stop, "no stable step", where a candidate
  // starts far off), and only where a candidate ends counts here.
  choice.solver = SolverOptions();
  choice.solver.num_threads = options.solver.num_threads;
  choice.solver.linear_solver = options.solver.linear_solver;
  choice.solver.sparse_library = options.solver.sparse_library;
  choice.solver.interrupt = options.solver.interrupt;
  choice.damping_groups = DampingGroups();
  choice.trajectory_per_decade = 0;
  choice.max_correspondence_rounds = max_rounds;
  choice.max_accelerated_rounds = max_rounds;
  Model fitted = model;
  GlobalRounds rounds(frame_points, model.state, model.state, choice, source,
                      &fitted, &fit);
  try {
    rounds.Start();
    TrajectoryRecorder recorder(0, &fitted, &fit.trajectory);
    rounds.Run(&recorder);
  } catch (const InputError&) {  // An unusable solve: no candidate.
    return {std::numeric_limits<double>::infinity(), model.Rotation().col(2),
            model};
  }
  Summarize(fitted, frame_points.positions, &fit);
  return {fit.rms_mm * fit.rms_mm, fitted.Rotation().col(2), fitted};
}

StartAxis ChooseStartAxis(const Frame& first, const ModelConfig& config,
                          const FitOptions& options,
                          const std::string& source) {
  const std::vector<Eigen::Vector3d> points = Positions(first);
  if (options.hint) {
    return {InitializeModel(config, points, options.hint),
            options.hint->source};
  }
  std::vector<Eigen::Vector3d> candidates;
  std::string axis_source;
  const auto planes = FindParallelPlanes(points);
  if (planes && !LengthOf(points).Across(planes->normal)) {
    candidates = {planes->normal};
    axis_source = PlanesSource(planes->count);
  } else {
    candidates = CandidateAxes(points);
    axis_source = "point cloud, best of " + std::to_string(candidates.size()) +
                  " candidate axes";
    // Planes across the cloud's length are no short-axis stack of it (on
    // 100-150 random tags, chance clumps passed FindParallelPlanes with a
    // normal 68-90 degrees from it; real stacks' lie within 7): their
    // normal competes with the cloud's axes, and pays 4 times the cost.
    if (planes) {
      candidates.push_back(planes->normal);
      axis_source +=
          " and the " + PlanesSource(planes->count) + " across its length";
    }
  }
  if (candidates.size() == 1) {
    return {InitializeModelAlong(config, points, candidates[0]), axis_source};
  }
  size_t winner = 0;
  const CandidateFit best =
      BestCandidate(first, config, candidates, options, source, &winner);
  // The principal axis starts as ever; another winner was a seed (its fit
  // turns 30-40 degrees from a direction halfway between two principal
  // axes), so frame 0 starts from where its fit turned to, pointed from
  // the narrower end as any axis.
  if (winner == 0) {
    return {InitializeModelAlong(config, points, candidates[0]), axis_source};
  }
  return {InitializeModelAlong(config, points, best.axis), axis_source};
}

}  // namespace pfdm
