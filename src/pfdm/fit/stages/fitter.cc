#include "pfdm/fit/stages/fitter.h"

#include <utility>

#include "pfdm/fit/stages/apex_coverage.h"
#include "pfdm/fit/stages/frame_fit.h"
#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/fit/stages/loss_scale.h"
#include "pfdm/fit/stages/start.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/fit/stages/wall_stage.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {

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
    result.frames.push_back(FitFrame(frame, reference, start.frames_per_id,
                                     options, sequence.source, &start.wall,
                                     &carried));
  }
  result.config = carried.model.config;
  result.wall_reason = start.wall.reason;
  result.axis_source = start.axis_source;
  result.ed_frame = options.ed_frame;
  result.time_ms = sequence.time_ms;
  result.left_out = sequence.left_out;
  result.temporal_prior_weight = options.temporal_prior_weight;
  result.start_seconds = start_seconds;
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
  JudgeFrames(sequence, options, &result);
  result.checks_seconds = SecondsSince(checks_time);
  return result;
}

}  // namespace pfdm
