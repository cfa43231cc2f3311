// A model's functions carried to another number of knots: what a fit on few
// knots (the start's screened candidates) hands to one on the model's own.
#ifndef PFDM_MODEL_KNOT_RESAMPLING_H_
#define PFDM_MODEL_KNOT_RESAMPLING_H_

#include "pfdm/model/model.h"

namespace pfdm {

// `model` on `config`'s knots: every free function sampled at them, the
// pose, globals and local field as they are.  Knots are uniform in sin u,
// so where model's knots are among config's (5 or 9 among 17: K - 1
// dividing config's K - 1) the functions are the same at every u;
// otherwise each is model's at config's knots, linear between them.
Model ResampleKnots(const Model& model, const ModelConfig& config);

}  // namespace pfdm

#endif  // PFDM_MODEL_KNOT_RESAMPLING_H_
