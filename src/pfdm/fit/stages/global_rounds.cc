#include "pfdm/fit/stages/global_rounds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "pfdm/fit/correspondence/frame_correspondence.h"
#include "pfdm/fit/correspondence/measured_depths.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/fit/stages/top_slice.h"
#include "pfdm/util/error.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// Frame 0 of at least twice this many points starts with a round on this
// many of them (SolveCoarse).  A round on 2,048 of 20,000 tags leaves the
// rounds on all points as many solves as one on 4,096, at half its cost.
constexpr size_t kCoarsePoints = 2048;
// A solid's predictor step (PredictsRound) on a frame of at least twice this
// many points takes this many of them.
constexpr size_t kPredictorPoints = 4096;
// The accelerated rounds measure each round's change at about this many of
// the untracked points (every k-th past twice as many): at all of 20,000
// tags, frame 0's two model evaluations a point were 4 % of it.
constexpr size_t kProbePoints = 4096;

// A correspondence round's search is skipped as confirmation when the one
// before moved no point by this many tolerances and the solve since moved
// the surface little (Settled).
constexpr double kConfirmBelow = 10.0;

// Accelerate keeps a mix whose points' summed squared distance to their
// closest points is at most this many times the plain round's.  The mixes
// of the test suite's fits and of biv-me's 25 frames ranged 0.86-1.18
// times; Zhang et al.'s bound of 1 left biv-me's frames unsettled (0.06-2.2
// mm).  A solid of both walls' contours of a mid-ventricular segment,
// its apex free, met a mix of 420 times, which crossed its walls (h -10 to
// -55 mm, RMS 5 mm), and the rounds never left that state.
constexpr double kMixDistanceGrowth = 2.0;

// Solves of a tracked frame of a solid, each after its tags were ranked:
// ranks against the previous frame's model left each layer's Ecc 1-1.5
// points off on the LV phantoms (lv_layer_strain_test), ranks against this
// frame's fit do not, and a third solve changes nothing visible.  The
// first solve only has to bring the model near this frame's fit, which
// one Gauss-Newton step does (PredictsRound): the problem is nearly linear
// about the previous frame's fit.
// Frame 0's tags through a solid's wall are ranked at this many searches
// too, and then held at their depths (DepthRanking::hold): at 6,000 wall
// tags, a third of them changed rank at every search, moving the rounds'
// farthest points 0.3-0.7 mm, and the rounds ran on until the skip rule or
// the round limit ended them (1,500 tags: out of rounds, 0.30 mm
// unsettled).  With the depths held, the slide that is left shrinks by
// about 0.7 a round and the rounds settle (docs/performance.md).
constexpr int kRerankRounds = 2;

// A later frame's contour rounds swing back when a round's change (at the
// probes) points against the last one's, cosine under kSwingCosine, and
// is at least kSwingKept of its size (a swing that halves each round dies
// out alone).  From then on each round of the frame is also pulled toward
// the state it starts from (FitOptions::swing_pull_weight, mixed into the
// frame's prior by PulledTowardStart, so with its scales).  The rounds are
// a fixed-point iteration; on biv-me's both walls most frames' rounds
// reversed at every round (cosine -0.9 to -1.0, each change 0.8-1.3 times
// the last: an eigenvalue of the map near -1, the centre going 0.3 mm
// along the axis and back, the wall's thickness at the apex 0.4 mm), and
// frames 8-10 never settled (20 rounds, 0.2-0.4 mm left).  A pull of
// weight w toward the round's start turns an eigenvalue m along a
// direction of stiffness H into (m H + w) / (H + w), and at a fixed point
// it pulls nothing.  Starting each round halfway back instead (a plain
// relaxation) left frames 8-10 unsettled: the map is not linear there.
//
// What the pull costs, and how it is contained:
// - It slows what does not swing, hence kSwingKept: pulled from a swing
//   that had shrunk to 0.37 of the change before, the phantom's second
//   contour frame (FitterTest) crept through 10 solves where plain ones
//   settle in 4.
// - It holds knots that few points see (biv-me's top knots: 2-5 points)
//   where the rounds found them: once the closest points settle, the frame
//   is solved once more on them without it (SolveUnpulled; without that
//   solve biv-me's frame 24's top section strayed 16 % from frame 0's).
// - Its damped steps understate how far the fixed point still is: pulled
//   rounds settle at kPulledTolerance of the tolerance (a frame that runs
//   out of rounds between the two has settled as plain ones would).
// - Frame 0 is never pulled (nor the start's candidates, also fitted as
//   frame 0): every later frame is measured against it, and a pulled frame
//   0 ends where its damped path left it.  Pulled, a hair's breadth (guide
//   points moved by 1e-5 mm, scripts/perturbation_sensitivity.py) moved
//   biv-me's cavity segments' Ecc by a median 0.6 points over the frames
//   at some weights (0.19 with plain rounds).
// Both walls: every frame settles, 206 -> 172 solves; the cavity 167 -> 171
// (docs/performance.md).
constexpr double kSwingCosine = -0.5;
constexpr double kSwingKept = 0.5;
constexpr double kPulledTolerance = 0.5;

// Every stride-th of the listed points, the stride leaving about `count`
// of them.
std::vector<size_t> Coarse(const std::vector<size_t>& which, size_t count) {
  const size_t stride = std::max<size_t>(1, which.size() / count);
  std::vector<size_t> coarse;
  for (size_t j = 0; j < which.size(); j += stride) coarse.push_back(which[j]);
  return coarse;
}

// The listed points with their material points and normals, as a frame's
// problem takes them.
struct PointSubset {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<MaterialPoint> material;
};
PointSubset Subset(const std::vector<size_t>& which,
                   const std::vector<Eigen::Vector3d>& points,
                   const std::vector<MaterialPoint>& material,
                   const std::vector<Eigen::Vector3d>& normals) {
  PointSubset subset;
  for (size_t i : which) {
    subset.points.push_back(points[i]);
    subset.material.push_back(material[i]);
    subset.normals.push_back(normals[i]);
  }
  return subset;
}

}  // namespace

GlobalRounds::GlobalRounds(const FramePoints& frame, const ModelState& prior,
                           const ModelState& reference,
                           const FitOptions& options, const std::string& source,
                           Model* model, FrameFit* fit)
    : frame_(frame),
      prior_(prior),
      reference_(reference),
      options_(options),
      source_(source),
      model_(model),
      fit_(fit),
      normals_(frame.positions.size(), Eigen::Vector3d::Zero()) {
  // Ranks among neighbours keep a segment's own motion out of the depths of
  // a frame ranked anew; held depths are ranked once, on frame 0, whose
  // rings have not moved, in their bands.
  ranking_.neighbourhoods = options.local.enabled && options.local.transmural &&
                            !options.hold_tag_depths;
  ranking_.measured = HasBothWalls(frame.layer_w);
  ranks_tags_ =
      std::any_of(frame.untracked.begin(), frame.untracked.end(),
                  [&frame](size_t i) { return frame.assign_depth[i]; });
  top_is_slice_ = model->config.Solid() && !frame.untracked.empty() &&
                  TopIsSlice(frame.positions, *model);
  may_pull_ = frame.kind != FrameKind::kReference &&
              std::none_of(frame.untracked.begin(), frame.untracked.end(),
                           [&frame](size_t i) { return frame.is_tag[i]; });
}

void GlobalRounds::set_rank_band_mm(double band_mm) {
  if (band_mm == ranking_.outlier_band_mm) return;
  ranking_.outlier_band_mm = band_mm;
  ranking_.hold = false;  // Ranked afresh within the new band.
  ranked_searches_ = 0;
}

void GlobalRounds::Start() {
  if (frame_.kind == FrameKind::kReference &&
      frame_.untracked.size() >= 2 * kCoarsePoints) {
    SolveCoarse();
  }
  moved_ = UpdateClosest();
  CheckInterrupt(options_.solver);
  // A solid's tracked tags keep (u, v) and, unless held (held_depths.h),
  // take their depth from this frame's ranks (RerankDepths), first against
  // the previous frame's fit:
  // a predictor's step from frame 0's depths instead read the wall
  // segment's thickening 3.1-3.3 points high (lv_wall_segment_test).
  // Measured depths (the contours place the walls) are material, as held
  // ones: measured again against the previous frame's walls, a tag would
  // read its own motion as depth.
  rerank_depths_ = model_->config.Solid() && !frame_.tracked.empty() &&
                   !hold_depths_ && !ranking_.measured;
  if (rerank_depths_) {
    RerankDepths(*model_, frame_.positions, frame_.tracked, &fit_->material,
                 ranking_);
  }
}

// Coarse to fine: a first round on every k-th point brings the initialized
// model to the data at a fraction of a round's cost, and the rounds on all
// points start from there (one round fewer).
void GlobalRounds::SolveCoarse() {
  const std::vector<size_t> coarse = Coarse(frame_.untracked, kCoarsePoints);
  const auto closest_start = Clock::now();
  pfdm::UpdateClosest(*model_, frame_.positions, coarse,
                      options_.solver.num_threads, frame_.layer_w,
                      frame_.assign_depth, false, &fit_->material, &normals_,
                      &found_, ranking_, grid_);
  fit_->correspondence_seconds += SecondsSince(closest_start);
  const PointSubset subset =
      Subset(coarse, frame_.positions, fit_->material, normals_);
  FitOptions coarse_options = options_;
  coarse_options.solver.on_step = nullptr;  // Not part of the path.
  const SolverReport coarse_report =
      SolveFrame({subset.points, subset.material, subset.normals, std::nullopt,
                  FrameKind::kReference, prior_, reference_},
                 coarse_options, model_);
  AddSolverCounts(coarse_report, fit_);
  SpanAxialExtent(frame_.positions, options_, model_,
                  RimLift(top_is_slice_, *model_));
}

void GlobalRounds::Search() { moved_ = UpdateClosest(); }

void GlobalRounds::Run(TrajectoryRecorder* recorder) {
  fit_->unsettled_mm = 0.0;
  acceleration_.reset();
  best_.reset();
  last_change_.resize(0);
  pulled_ = false;
  int max_rounds = options_.max_correspondence_rounds;
  // The rounds past max_correspondence_rounds (mixed, the best kept) run
  // only where plain ones did not settle, so a frame that settles is as it
  // was.  A tag's first frame needs them as contours do: a near-round LV's
  // spin is nearly free, and the LV phantom's noise-free tags (seed 1004)
  // swung it by 0.1 rad a round, a tag's closest point by 5.3 mm, ending
  // at RMS 0.42 mm where the better of the two states has 0.004.
  if (!rerank_depths_ && !frame_.untracked.empty()) {
    acceleration_.emplace();
    probes_ = Listed(fit_->material, Coarse(frame_.untracked, kProbePoints));
    max_rounds = options_.max_accelerated_rounds;
  }
  for (int round = 0; round < max_rounds; ++round) {
    CheckInterrupt(options_.solver);  // After the search, before the solve.
    const Model before = *model_;
    report_ = SolveRound(recorder, PredictsRound(round));
    CheckUsable();
    if (Settled(round, max_rounds)) {
      if (pulled_) SolveUnpulled(recorder);
      break;
    }
    if (!acceleration_) continue;
    Eigen::VectorXd change =
        ProbePoints(*model_, probes_) - ProbePoints(before, probes_);
    NoteSwing(change);
    if (round + 1 < max_rounds) Accelerate(round, std::move(change));
  }
}

void GlobalRounds::SolveUnpulled(TrajectoryRecorder* recorder) {
  pulled_ = false;
  report_ = SolveRound(recorder, /*predictor=*/false);
  CheckUsable();
}

void GlobalRounds::CheckUsable() const {
  if (report_.usable) return;
  throw InputError(source_ + ": frame " + std::to_string(frame_.index) +
                   ": solver failed: " + report_.message);
}

void GlobalRounds::NoteSwing(const Eigen::VectorXd& change) {
  if (may_pull_ && options_.swing_pull_weight > 0.0 &&
      last_change_.size() == change.size() &&
      change.norm() > kSwingKept * last_change_.norm() &&
      change.dot(last_change_) <
          kSwingCosine * change.norm() * last_change_.norm()) {
    pulled_ = true;
  }
  last_change_ = change;
}

void GlobalRounds::Accelerate(int round, Eigen::VectorXd change) {
  const Eigen::VectorXd solution = StateVector(model_->state);
  const Eigen::VectorXd next = acceleration_->Next(std::move(change), solution);
  // The first max_correspondence_rounds rounds are plain, as every frame's
  // were: the mix only takes over rounds that would have run out.  Mixed
  // from the start, the contours of a moving phantom (FitterTest) took 20
  // rounds where plain ones settle in 9.
  if (round + 1 < options_.max_correspondence_rounds || next == solution) {
    return;
  }
  // A mix that takes the points far from their closest points is dropped
  // for the plain round, and the mix starts afresh (Zhang et al.'s
  // safeguard, kMixDistanceGrowth): a steady creep makes successive changes
  // alike, and the mix of them a leap.
  const double plain_distance = SquaredDistanceToFound();
  Snapshot plain = Take();
  SetStateVector(next, &model_->state);
  moved_ = UpdateClosest();
  if (SquaredDistanceToFound() <= kMixDistanceGrowth * plain_distance) return;
  Restore(std::move(plain));
  acceleration_->Restart();
}

double GlobalRounds::SquaredDistanceToFound() const {
  double sum = 0.0;
  for (size_t j = 0; j < frame_.untracked.size(); ++j) {
    sum += (frame_.positions[frame_.untracked[j]] - found_[j]).squaredNorm();
  }
  return sum;
}

GlobalRounds::Snapshot GlobalRounds::Take() const {
  return {moved_,   model_->state, fit_->material, found_,
          normals_, report_,       fit_->costs};
}

void GlobalRounds::Restore(Snapshot snapshot) {
  moved_ = snapshot.moved;
  model_->state = std::move(snapshot.state);
  fit_->material = std::move(snapshot.material);
  found_ = std::move(snapshot.found);
  normals_ = std::move(snapshot.normals);
  normals_current_ = true;
  report_ = std::move(snapshot.report);
  fit_->costs = snapshot.costs;
}

void GlobalRounds::KeepBest() {
  if (best_ && best_->moved <= moved_) return;
  best_ = Take();
}

void GlobalRounds::BackToBest() {
  if (!best_ || best_->moved >= moved_) return;
  Restore(std::move(*best_));
  best_.reset();
}

// Only the direct solve takes its step at once: the damped solvers' and the
// integrator's steps are their dynamics, each a fraction of the way.
bool GlobalRounds::PredictsRound(int round) const {
  return rerank_depths_ && round + 1 < kRerankRounds &&
         options_.solver.kind == SolverKind::kDirect;
}

SolverReport GlobalRounds::SolveRound(TrajectoryRecorder* recorder,
                                      bool predictor) {
  std::optional<double> rim_height;
  if (frame_.kind != FrameKind::kReference && !frame_.untracked.empty()) {
    const double top = TopHeight(frame_.positions, options_, *model_);
    rim_lift_ = RimLift(top_is_slice_, *model_);
    if (std::isfinite(top)) rim_height = top + rim_lift_;
  }
  const SolverTracePoint last =
      fit_->trace.empty() ? SolverTracePoint{-1} : fit_->trace.back();
  FitOptions round_options = options_;
  if (predictor) round_options.solver.max_iterations = 1;
  if (options_.trajectory_per_decade > 0) {
    round_options.solver.on_step = [recorder,
                                    last](const SolverTracePoint& point) {
      recorder->Step(last.iteration + 1 + point.iteration,
                     last.pseudo_time + point.pseudo_time);
    };
  }
  if (!normals_current_) {
    normals_ = SlidingNormals(*model_, fit_->material, frame_.sliding);
  }
  FramePrior prior{prior_, round_options};
  if (pulled_) {
    prior = PulledTowardStart(frame_.kind, prior_, round_options, model_->state,
                              options_.swing_pull_weight);
  }
  SolverReport report;
  if (predictor && frame_.positions.size() >= 2 * kPredictorPoints) {
    // Near is all a predictor needs, as frame 0's coarse round.
    std::vector<size_t> all(frame_.positions.size());
    std::iota(all.begin(), all.end(), size_t{0});
    const PointSubset subset =
        Subset(Coarse(all, kPredictorPoints), frame_.positions, fit_->material,
               normals_);
    report = SolveFrame({subset.points, subset.material, subset.normals,
                         rim_height, frame_.kind, prior.state, reference_},
                        prior.options, model_);
  } else {
    report = SolveFrame({frame_.positions, fit_->material, normals_, rim_height,
                         frame_.kind, prior.state, reference_},
                        prior.options, model_, &fit_->costs);
  }
  normals_current_ = false;
  AddSolverCounts(report, fit_);
  ++fit_->correspondence_rounds;
  for (SolverTracePoint point : report.trace) {
    point.iteration += last.iteration + 1;
    point.pseudo_time += last.pseudo_time;
    point.wall_seconds += last.wall_seconds;
    fit_->trace.push_back(point);
  }
  return report;
}

bool GlobalRounds::Settled(int round, int max_rounds) {
  const double tolerance =
      options_.correspondence_tolerance_mm * (pulled_ ? kPulledTolerance : 1.0);
  if (rerank_depths_) {
    // Ranks settle in a round or two; later rounds only trade noise
    // between tags (kRerankRounds).
    if (round + 1 >= kRerankRounds) return true;
    // A predictor's step is not a solve's end, whatever the ranks did.
    if (PredictsRound(round)) {
      RerankDepths(*model_, frame_.positions, frame_.tracked, &fit_->material,
                   ranking_);
      return false;
    }
    double moved = 0.0;
    RerankDepths(*model_, frame_.positions, frame_.tracked, &fit_->material,
                 ranking_, &moved);
    return moved < tolerance;
  }
  if (frame_.untracked.empty()) return true;
  if (frame_.kind == FrameKind::kReference) {
    SpanAxialExtent(frame_.positions, options_, model_,
                    RimLift(top_is_slice_, *model_));
  }
  // A later frame's rim target took its walls' drop as the solve began
  // (RimLift): the rounds go on while the drop moves.
  const double rim_moved =
      frame_.kind == FrameKind::kReference
          ? 0.0
          : std::abs(RimLift(top_is_slice_, *model_) - rim_lift_);
  // Near convergence, how far the solve moved the surface under the
  // points bounds how far their closest points can move (about that far,
  // the points being close to a gently curved surface): under half the
  // tolerance, the search that would confirm it is skipped.
  std::vector<Eigen::Vector3d> now;
  if (moved_ < kConfirmBelow * tolerance && rim_moved < 0.5 * tolerance) {
    now = WorldPoints(*model_, Listed(fit_->material, frame_.untracked));
    if (MaxDistance(now, found_) < 0.5 * tolerance) return true;
  }
  moved_ = std::max(UpdateClosest(std::move(now)), rim_moved);
  if (moved_ < tolerance) return true;
  if (acceleration_) KeepBest();
  if (round + 1 == max_rounds) {
    BackToBest();
    // Pulled rounds that end between their tolerance and the frame's have
    // settled as plain ones would.
    if (moved_ >= options_.correspondence_tolerance_mm) {
      fit_->unsettled_mm = moved_;
    }
  }
  return false;
}

double GlobalRounds::UpdateClosest(std::vector<Eigen::Vector3d> now) {
  const auto closest_start = Clock::now();
  if (found_closest_ && now.empty()) {
    now = WorldPoints(*model_, Listed(fit_->material, frame_.untracked));
  }
  pfdm::UpdateClosest(*model_, frame_.positions, frame_.untracked,
                      options_.solver.num_threads, frame_.layer_w,
                      frame_.assign_depth, found_closest_, &fit_->material,
                      &normals_, &found_, ranking_, grid_);
  const double moved = found_closest_ || frame_.untracked.empty()
                           ? MaxDistance(now, found_)
                           : std::numeric_limits<double>::infinity();
  found_closest_ = true;
  normals_current_ = true;
  if (model_->config.Solid() && ranks_tags_ &&
      ++ranked_searches_ >= kRerankRounds) {
    ranking_.hold = true;
  }
  fit_->correspondence_seconds += SecondsSince(closest_start);
  return moved;
}

}  // namespace pfdm
