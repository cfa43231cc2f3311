#include "pfdm/fit/stages/temporal_prior.h"

#include "glog/logging.h"

namespace pfdm {

double TemporalPriorWeightFor(int num_frames, const FitOptions& options) {
  return num_frames >= kTemporalPriorMinFrames ? options.temporal_prior_weight
                                               : 0.0;
}

namespace {

// a * x + b * y, function by function, globals and knots.
ModelState MixedFunctions(double a, const ModelState& x, double b,
                          const ModelState& y) {
  CHECK_EQ(x.knots.size(), y.knots.size());
  ModelState mixed = x;
  for (int f = 0; f < kNumFunctions; ++f) {
    mixed.globals[f] = a * x.globals[f] + b * y.globals[f];
  }
  for (size_t k = 0; k < x.knots.size(); ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      mixed.knots[k][f] = a * x.knots[k][f] + b * y.knots[k][f];
    }
  }
  return mixed;
}

}  // namespace

FramePrior PriorOfFrame(FrameKind kind, const ModelState& reference,
                        const ModelState& previous, bool previous_is_reference,
                        const FitOptions& options) {
  if (kind != FrameKind::kUntracked) return {previous, options};
  const double w0 = options.untracked_prior_weight;
  const double w1 = options.temporal_prior_weight;
  if (w1 <= 0.0 || previous_is_reference) return {reference, options};
  FramePrior prior{
      MixedFunctions(w0 / (w0 + w1), reference, w1 / (w0 + w1), previous),
      options};
  prior.options.untracked_prior_weight = w0 + w1;
  return prior;
}

FramePrior PulledTowardStart(FrameKind kind, const ModelState& prior,
                             const FitOptions& options, const ModelState& start,
                             double weight) {
  FramePrior pulled{prior, options};
  double& w0 = kind == FrameKind::kUntracked
                   ? pulled.options.untracked_prior_weight
                   : pulled.options.prior_weight;
  pulled.state =
      MixedFunctions(w0 / (w0 + weight), prior, weight / (w0 + weight), start);
  w0 += weight;
  return pulled;
}

}  // namespace pfdm
