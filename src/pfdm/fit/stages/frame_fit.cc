#include "pfdm/fit/stages/frame_fit.h"

#include <algorithm>

#include "pfdm/fit/correspondence/measured_depths.h"
#include "pfdm/fit/stages/apex_coverage.h"
#include "pfdm/fit/stages/frame_summary.h"
#include "pfdm/fit/stages/frame_uncertainty.h"
#include "pfdm/fit/stages/global_rounds.h"
#include "pfdm/fit/stages/local_noise.h"
#include "pfdm/fit/stages/local_stage.h"
#include "pfdm/fit/stages/loss_scale.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/fit/stages/trajectory_recorder.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// Frame 0 of tags keeps the start's spin about the long axis where the
// data leave it free (FitOptions::reference_spin_weight).  Frame 0 holds
// tau, so the pose's spin is where v = 0 lies and which material point
// each tag keeps for every later frame; on a round section (the LV
// phantom: a1 = a2 to 1e-3) only noise decides it, and the closest-point
// rounds crept along it 0.6-0.7 mm a round until the mixed rounds settled
// it (2,000 wall tags: 20 rounds, 212 ms; 7 with it, 55 ms).  At 1e-3 a
// point the data of a section of ellipticity 0.1 keep their spin against a
// 0.2 rad pull to within 0.015 rad in one solve (FrameProblemTest), and
// the start's x axis, the data's widest direction across the axis, is near
// their choice anyway; 1e-4 left the rounds creeping.  A solid's contours
// need it too: their point-to-plane pulls, fixed along the normals of the
// last search, let the pose spin a round section at no cost to first
// order and take in 1 mm of radius (the chord's second order) for the
// prior's sake; the noise-free LV phantom's both walls' short-axis contours
// spun 0.25 rad a solve, every other search jumped 9 mm and frame 0 never
// settled.  A mid-wall's contours are left as they were: on biv-me's they
// settle without it, and with it two frames ended 0.05 mm unsettled
// (docs/performance.md, 2026-12-04).
constexpr double kReferenceSpinWeight = 1e-3;
// Frame 0's pull toward the start's apex height (ApexGaugeResidual) where
// no data reach the apex (ApexInData, asked of the start), as weak as the
// spin's.  On the LV phantom's mid-ventricular segment (1,500 mid-wall
// tags) the rounds had moved the apex 6.3 mm; with it 1.6 mm, and they
// settle.  Held firmer (1e-2: 0.2 mm), the noisy prolate segment's
// thickening read 3.2 points high at frame 1 against 2.3 without the pull
// and 2.8 with this one (lv_wall_segment_test.cc): what a segment without
// an apex says depends on where the fit puts the apex it cannot see.
constexpr double kReferenceApexWeight = 1e-3;
// The same pull where frame 0 has no tags (contours), firmer, where the
// data stop short of the apex by more than kContourApexPullReach of the
// length: nothing else holds it there.  Each round's solve slid the model
// of both walls' contours of a mid-ventricular segment (the data 0.4-0.5
// of the length from the apex) 1.8 mm toward its base, and the length's
// reset (SpanAxialExtent) kept the apex there, so the model shortened a
// round at a time: 12 mm in ten rounds, RMS 1.1-1.4 mm at 0.5 mm noise.  At
// 1e-3 it still crept; at 0.1 the rounds settle in five (RMS 0.75-0.88,
// the same as at 1) with the apex 0.43 of the length below the data (0.42
// true).  A short-axis stack's lowest epicardial slice (0.16 of the length
// away) holds its apex: pulled there, frame 0's length covered 0.92 (0.95
// free), since the pull's target, the start's apex, moves with the noise
// and the covariance holds it fixed.
constexpr double kReferenceContourApexWeight = 0.1;
constexpr double kContourApexPullReach = 0.3;

// The frame's global rounds, and on frame 0 with the wall undecided, the
// wall: a solid runs the rounds again.  With --loss_scale auto, the rounds
// run without the loss until they settle (and the wall is decided), then
// measure the frame's scale and go on with the loss.
void FitGlobal(const FramePoints& points, const ModelState& prior,
               const FitOptions& options, const std::string& source,
               WallDecision* wall, CarriedState* carried, FrameFit* fit) {
  Model& model = carried->model;
  const bool reference = points.kind == FrameKind::kReference;
  const bool measure = MeasuresLossScale(options);
  // The rounds read these at every solve.
  FitOptions round_options = measure ? WithoutLoss(options) : options;
  GlobalRounds rounds(points, prior, carried->reference, round_options, source,
                      &model, fit);
  rounds.set_surface_grid(&carried->surface_grid);
  if (carried->depths_held) rounds.hold_depths();
  if (options.loss != "none" && !measure) {
    fit->loss_scale_mm = options.loss_scale_mm;
    if (reference) carried->reference_loss_scale_mm = fit->loss_scale_mm;
    rounds.set_rank_band_mm(
        RankBandMm(options.loss, carried->reference_loss_scale_mm));
  }
  rounds.Start();
  TrajectoryRecorder recorder(options.trajectory_per_decade, &model,
                              &fit->trajectory);
  rounds.Run(&recorder);
  if (reference && !wall->decided &&
      DecideWallFromTags(points, fit->material, rounds.report().converged,
                         options.wall, wall, &model)) {
    // Outliers inside the wall take the extreme ranks, whose ends a cubic
    // depth follows: with 5 % of them the squeeze read the LV phantom's
    // cavity 2-3.5 % small against the clean fit (docs/gauge.md), so a fit
    // with a robust loss keeps the quadratic depth.
    if (options.loss != "none") {
      model.config.modes[kWallSqueeze] = FunctionMode::kFixed;
    }
    rounds.Search();
    rounds.Run(&recorder);
  }
  if (measure) {
    fit->loss_scale_mm =
        MeasureLossScale(options.loss, model, points.positions, fit->material);
    if (reference) carried->reference_loss_scale_mm = fit->loss_scale_mm;
    round_options = WithLossScale(options, fit->loss_scale_mm);
    rounds.set_rank_band_mm(
        RankBandMm(options.loss, carried->reference_loss_scale_mm));
    rounds.Run(&recorder);
  }
  recorder.Finish();
  fit->termination = rounds.report().termination;
}

// The frame's new tags keep the material points found here for the frames
// after it.
void RememberTags(const Frame& frame, const FramePoints& points,
                  const FrameFit& fit, TrackedMaterial* tracked_material) {
  for (size_t i : points.untracked) {
    if (points.is_tag[i]) {
      (*tracked_material)[frame.points[i].id] = fit.material[i];
    }
  }
}

// The frame's bending into its final gauge, and the recorded path with it.
void CanonicalizeBending(Model* model, FrameFit* fit) {
  const BendingShift turns = model->CanonicalizeBending();
  if (turns == BendingShift{0.0, 0.0}) return;
  for (TrajectoryPoint& point : fit->trajectory) {
    Model recorded{model->config, point.state};
    recorded.ShiftBending(turns);
    point.state = recorded.state;
  }
}

// Whether the frame's points show its turn about the axis (FrameFit::tracked).
bool HasTrackedPoints(const FramePoints& points) {
  switch (points.kind) {
    case FrameKind::kReference:
      return std::find(points.is_tag.begin(), points.is_tag.end(), true) !=
             points.is_tag.end();
    case FrameKind::kTracked:
      return true;
    case FrameKind::kUntracked:
      return false;
  }
  return false;
}

// Frame 0's data's u range, where the wall keeps its volume.
void RememberDataSpan(const std::vector<MaterialPoint>& material,
                      CarriedState* carried) {
  if (material.empty()) return;
  const auto [low, high] = std::minmax_element(
      material.begin(), material.end(),
      [](const MaterialPoint& a, const MaterialPoint& b) { return a.u < b.u; });
  carried->data_u_low = low->u;
  carried->data_u_high = high->u;
}

}  // namespace

FrameFit FitFrame(const Frame& frame, bool reference,
                  const FramesPerId& frames_per_id,
                  const FitOptions& sequence_options, const std::string& source,
                  WallDecision* wall, CarriedState* carried) {
  const auto start = Clock::now();
  Model& model = carried->model;
  // The global rounds fit the global model alone; the local field comes
  // after them.
  model.state.local = LocalField();
  FrameFit fit;
  fit.frame = frame.index;
  const FramePoints points =
      MakeFramePoints(frame, reference, frames_per_id,
                      carried->tracked_material, &fit.material);
  fit.kind = points.kind;
  fit.tracked = HasTrackedPoints(points);
  fit.depths_held = carried->depths_held && model.config.Solid() &&
                    points.kind == FrameKind::kTracked;
  fit.mixed = HasContoursBesideTags(points);
  fit.depths_measured = model.config.Solid() && HasBothWalls(points.layer_w) &&
                        std::any_of(points.is_tag.begin(), points.is_tag.end(),
                                    [](bool tag) { return tag; });
  const FramePrior frame_prior = PriorOfFrame(
      points.kind, carried->reference, carried->previous,
      /*previous_is_reference=*/carried->frames_fitted <= 1, sequence_options);
  const ModelState& prior = frame_prior.state;
  FitOptions options = frame_prior.options;
  options.incompressible_u_low = carried->data_u_low;
  options.incompressible_u_high = carried->data_u_high;
  if (reference && fit.tracked) {
    options.reference_spin_weight = kReferenceSpinWeight;
    if (!ApexInData(model, points.positions)) {
      options.reference_apex_weight = kReferenceApexWeight;
    }
  } else if (reference) {
    if (model.config.Solid()) {
      options.reference_spin_weight = kReferenceSpinWeight;
    }
    if (!ApexInData(model, points.positions, kContourApexPullReach)) {
      options.reference_apex_weight = kReferenceContourApexWeight;
    }
  } else if (points.kind == FrameKind::kUntracked) {
    // Where the data reach the apex, they and the base rim say how long
    // the model is; the pull toward frame 0's length held end-systole long
    // (the LV phantom's short- and long-axis contours: shortening 14.6 %
    // against 17.0, now 16.6; biv-me's, against its meshes' own apex to rim
    // centroid: 11.1 % at frame 10 against 19.4, now 17.5).
    options.untracked_prior_holds_length = !ApexInData(model, points.positions);
  }
  CheckInterrupt(options.solver);
  FitGlobal(points, prior, options, source, wall, carried, &fit);
  RememberTags(frame, points, fit, &carried->tracked_material);
  CanonicalizeBending(&model, &fit);
  if (options.uncertainty) {
    fit.covariance = MeasureFrameCovariance(
        points, fit.material, prior, carried->reference,
        WithLossScale(options, fit.loss_scale_mm), model, fit.depths_held);
    // Frame 0's length is set by its highest points and held; an untracked
    // later frame's base rim is held at its own highest (contours).
    if (fit.covariance.computed && (reference || !fit.tracked)) {
      fit.covariance.length_noise = LengthNoiseDraws(
          points, fit.material, WithLossScale(options, fit.loss_scale_mm),
          model, fit.covariance.sigma_mm);
    }
    // Frame 0's length is the top less the fitted apex: the draws move the
    // top, the covariance the apex.
    const double length = AxialLength(model);
    if (fit.covariance.computed && reference && length > 0.0) {
      fit.covariance.apex_length_variance =
          ApexAxialVariance(fit.covariance, model) / (length * length);
    }
  }
  CheckInterrupt(options.solver);
  if (options.local.enabled) {
    const FitOptions local_options = WithLossScale(options, fit.loss_scale_mm);
    FitLocalStage(points, local_options, source, &model, &fit,
                  &carried->local_solver, &carried->local_surface_grid);
    if (fit.covariance.computed) {
      fit.covariance.local_noise =
          LocalNoiseDraws(points, fit.material, local_options, model,
                          fit.covariance.NoiseSigma());
    }
  }
  Summarize(model, points.positions, &fit);
  CheckFinite(source, fit);
  fit.solve_seconds = SecondsSince(start);
  carried->previous = model.state;
  if (reference) {
    carried->reference = model.state;
    RememberDataSpan(fit.material, carried);
  }
  ++carried->frames_fitted;
  return fit;
}

}  // namespace pfdm
