// Fits a model to every frame of a point sequence, as a pipeline of stages
// (docs/architecture.md "One frame's fit"): the start, then each frame's
// global correspondence rounds, the wall, the local field and the summary,
// then the solid's tag noise.
#ifndef PFDM_FIT_STAGES_FITTER_H_
#define PFDM_FIT_STAGES_FITTER_H_

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Gauge: see gauge.h and README "Gauge conventions".  The wall
// (options.wall, docs/gauge.md "The wall"): a solid when the first frame
// has contours of both walls, or tags spread across the wall by at least
// kMinWallSpreadMm after a converged mid-wall fit of that frame, outliers
// left out (RobustWallSpreadMm); a single
// surface otherwise.  The pull toward the previous frame
// (options.temporal_prior_weight) applies to sequences of
// kTemporalPriorMinFrames or more (temporal_prior.h), and the result
// records what was used.  Throws InputError naming the frame when a frame
// has too few points or the solver fails, and when --wall solid meets data
// with neither.
SequenceFit FitSequence(const PointSequence& sequence,
                        const ModelConfig& config, const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FITTER_H_
