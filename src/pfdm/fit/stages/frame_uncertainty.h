// How sure the frame's global fit is of its parameters: the covariance of
// the frame's problem at its global solution (frame_covariance.h), with the
// material points, normals, rim and prior the last solve had.
#ifndef PFDM_FIT_STAGES_FRAME_UNCERTAINTY_H_
#define PFDM_FIT_STAGES_FRAME_UNCERTAINTY_H_

#include <array>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/model/model.h"

namespace pfdm {

// `options` with the frame's loss scale; `model` the global solution
// (no local field), `material` the frame's final material points;
// `depths_held` as FrameFit's (EstimateFrameCovariance).
FrameCovariance MeasureFrameCovariance(
    const FramePoints& points, const std::vector<MaterialPoint>& material,
    const ModelState& prior, const ModelState& reference,
    const FitOptions& options, const Model& model, bool depths_held);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FRAME_UNCERTAINTY_H_
