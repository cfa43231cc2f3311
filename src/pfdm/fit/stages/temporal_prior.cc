#include "pfdm/fit/stages/temporal_prior.h"

#include "glog/logging.h"

namespace pfdm {

double TemporalPriorWeightFor(int num_frames, const FitOptions& options) {
  return num_frames >= kTemporalPriorMinFrames ? options.temporal_prior_weight
                                               : 0.0;
}

FramePrior PriorOfFrame(FrameKind kind, const ModelState& reference,
                        const ModelState& previous, bool previous_is_reference,
                        const FitOptions& options) {
  if (kind != FrameKind::kUntracked) return {previous, options};
  const double w0 = options.untracked_prior_weight;
  const double w1 = options.temporal_prior_weight;
  if (w1 <= 0.0 || previous_is_reference) return {reference, options};
  CHECK_EQ(reference.knots.size(), previous.knots.size());
  FramePrior prior{reference, options};
  prior.options.untracked_prior_weight = w0 + w1;
  const double a = w0 / (w0 + w1), b = w1 / (w0 + w1);
  for (int f = 0; f < kNumFunctions; ++f) {
    prior.state.globals[f] = a * reference.globals[f] + b * previous.globals[f];
  }
  for (size_t k = 0; k < reference.knots.size(); ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      prior.state.knots[k][f] =
          a * reference.knots[k][f] + b * previous.knots[k][f];
    }
  }
  return prior;
}

}  // namespace pfdm
