#include "pfdm/fit/stages/fitter.h"

#include <optional>
#include <utility>

#include "pfdm/fit/correspondence/measured_depths.h"
#include "pfdm/fit/stages/apex_coverage.h"
#include "pfdm/fit/stages/frame_fit.h"
#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/fit/stages/loss_scale.h"
#include "pfdm/fit/stages/start.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/fit/stages/wall_stage.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// Where frame 0's contours place both walls the tags' depths are measured
// (measured_depths.h), not ranked, and held whatever the option
// (FitSequence), shrunk by ShrinkMeasuredDepths.  A transmural local field
// holds them too (since 2026-12-07: docs/local_deformations.md).
bool HoldsTagDepths(const FitOptions& options, const Frame& first) {
  return options.hold_tag_depths && !HasBothWalls(first);
}

// What a frame's fit changes of the carried state (the searches' grids and
// the local solver's factors aside, which any frame may reuse).
struct FrameStart {
  explicit FrameStart(const CarriedState& carried)
      : model(carried.model),
        previous(carried.previous),
        reference(carried.reference),
        frames_fitted(carried.frames_fitted),
        tracked_material(carried.tracked_material) {}
  void Restore(CarriedState* carried) const {
    carried->model = model;
    carried->previous = previous;
    carried->reference = reference;
    carried->frames_fitted = frames_fitted;
    carried->tracked_material = tracked_material;
  }
  Model model;
  ModelState previous, reference;
  int frames_fitted;
  TrackedMaterial tracked_material;
};

// Whether some of the frame's points keep a material point from an earlier
// frame (FrameKind::kTracked).
bool TracksPoints(const Frame& frame, const TrackedMaterial& tracked) {
  for (const DataPoint& p : frame.points) {
    if (tracked.count(p.id) > 0) return true;
  }
  return false;
}

// The first tracked frame of a solid's tags is fitted once with its tags
// ranked (or at frame 0's measured depths), the global model only (the
// pilot), to measure their noise (FrameTagNoiseMm from neighbouring tags:
// the global model's misfit is not noise the depths should be shrunk for),
// which the held depths need.  Frame 0's tags then take their held depths
// (HoldTagDepths), or their measured ones shrunk (ShrinkMeasuredDepths), and
// *carried is as it was before the pilot, but for them.  Returns the pilot,
// whose cost is its frame's.
FrameFit FitPilot(const PointSequence& sequence, const Frame& frame,
                  const FramesPerId& frames_per_id, const FitOptions& options,
                  const FrameFit& first, WallDecision* wall,
                  CarriedState* carried) {
  const FrameStart before(*carried);
  FitOptions pilot_options = options;
  pilot_options.local.enabled = false;
  pilot_options.uncertainty = false;
  FrameFit pilot = FitFrame(frame, false, frames_per_id, pilot_options,
                            sequence.source, wall, carried);
  const ModelConfig& config = before.model.config;
  const Model reference = GlobalModelOf(config, first);
  const std::optional<double> sigma = FrameTagNoiseMm(
      GlobalModelOf(config, pilot), frame, pilot.material, frames_per_id,
      options.loss != "none", TagNoiseFrom::kNeighbours, &reference);
  before.Restore(carried);
  if (!sigma) return pilot;
  if (first.depths_measured) {
    ShrinkMeasuredDepths(reference, *sigma, &carried->tracked_material);
  } else {
    HoldTagDepths(sequence.frames[0], reference, *sigma,
                  &carried->tracked_material);
  }
  carried->depths_held = carried->depths_shrunk = true;
  return pilot;
}

// The pilot's solves and searches counted in the frame's.
void AddPilotCosts(const FrameFit& pilot, FrameFit* fit) {
  fit->iterations += pilot.iterations;
  fit->correspondence_rounds += pilot.correspondence_rounds;
  fit->solve_seconds += pilot.solve_seconds;
  fit->residual_evaluations += pilot.residual_evaluations;
  fit->jacobian_evaluations += pilot.jacobian_evaluations;
  fit->evaluation_seconds += pilot.evaluation_seconds;
  fit->linear_solver_seconds += pilot.linear_solver_seconds;
  fit->minimizer_seconds += pilot.minimizer_seconds;
  fit->correspondence_seconds += pilot.correspondence_seconds;
}

}  // namespace

SequenceFit FitSequence(const PointSequence& sequence,
                        const ModelConfig& config,
                        const FitOptions& given_options) {
  FitOptions options = given_options;
  options.temporal_prior_weight = TemporalPriorWeightFor(
      static_cast<int>(sequence.frames.size()), given_options);
  const auto start_time = Clock::now();
  SequenceStart start = StartSequence(sequence, config, options);
  const double start_seconds = SecondsSince(start_time);
  CheckInterrupt(options.solver);
  CarriedState carried(start.model);
  SequenceFit result;
  for (const Frame& frame : sequence.frames) {
    const bool reference = frame.index == sequence.frames[0].index;
    std::optional<FrameFit> pilot;
    const bool holds = HoldsTagDepths(options, sequence.frames[0]) ||
                       (!reference && result.frames[0].depths_measured);
    if (!reference && holds && start.has_tags && carried.model.config.Solid() &&
        !carried.depths_shrunk &&
        TracksPoints(frame, carried.tracked_material)) {
      pilot = FitPilot(sequence, frame, start.frames_per_id, options,
                       result.frames[0], &start.wall, &carried);
    }
    FrameFit fit = FitFrame(frame, reference, start.frames_per_id, options,
                            sequence.source, &start.wall, &carried);
    if (pilot) AddPilotCosts(*pilot, &fit);
    // Depths measured across frame 0's walls are material: frames without
    // both walls' contours keep them too (ranked there, mid-wall tags read
    // a wall 83 % thinner than frame 0's; measured_depths.h), the pilot
    // included.
    if (reference && fit.depths_measured) carried.depths_held = true;
    result.frames.push_back(std::move(fit));
  }
  result.config = carried.model.config;
  result.wall_reason = start.wall.reason;
  result.axis_source = start.axis_source;
  result.ed_frame = options.ed_frame;
  result.time_ms = sequence.time_ms;
  result.left_out = sequence.left_out;
  result.temporal_prior_weight = options.temporal_prior_weight;
  result.start_seconds = start_seconds;
  result.threads = options.solver.num_threads;
  const auto checks_time = Clock::now();
  result.surface =
      result.config.Solid() ? WallLayer::kAnywhere : start.wall.surface;
  if (result.config.Solid() && start.has_tags) {
    TakeOutTagNoise(sequence, start.frames_per_id, &result,
                    /*robust=*/options.loss != "none");
  }
  CheckInterrupt(options.solver);
  WeighPoints(options.loss, &result);
  MeasureApexCoverage(Positions(sequence.frames[0]), &result);
  JudgeFrames(sequence, start.frames_per_id, options, &result);
  result.checks_seconds = SecondsSince(checks_time);
  return result;
}

}  // namespace pfdm
