// The local field's share of the noise, by sampling.  The local field is
// the linear least-squares fit of what the global model leaves (its data
// residual, local_fit.h), so what the data's noise puts into it is the same
// fit of noise alone: the global model's own points at the data's material
// points, moved by draws of noise of the frame's measured spread, fitted
// with the frame's points, weights and stiffness.  Each draw is one such
// field; report/local_field_noise.h adds them to the fitted field and
// measures every number on the result: their spread is what the field
// adds to a number's variance, their mean shift the bias the noise puts
// into a number that is not linear in the field (Green-Lagrange strain is
// quadratic in the deformation gradient: on the LV phantom's 400 noisy
// tags the fitted field's wiggles made GCS 0.7 points less negative than
// the noise-free fit's, 5 of its sds; without the local field 0.03).
#ifndef PFDM_FIT_STAGES_LOCAL_NOISE_H_
#define PFDM_FIT_STAGES_LOCAL_NOISE_H_

#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Draws per frame: the bias's standard error is the field's own sd of a
// number over sqrt(draws), under a tenth of GCS's bias on the LV phantom.
inline constexpr int kLocalNoiseDraws = 12;
// Draws of frame 0's length: cheap (no solve), so enough that their mean,
// the length's bias, is known to a tenth of their spread.
inline constexpr int kLengthNoiseDraws = 100;

// `draws` local fields (their values, LocalField::values' layout) fitted to
// noise of sd sigma_mm per residual coordinate about `model`'s global
// surface (its local field left out) at `material`: tracked points in every
// coordinate, points searched on this frame (contours, tags on their first
// frame) along the surface's normal, fitted as the local stage fits them.
// Seeded by the frame's index, so a fit's outputs do not change from run to
// run.
std::vector<std::vector<double>> LocalNoiseDraws(
    const FramePoints& points, const std::vector<MaterialPoint>& material,
    const FitOptions& options, const Model& model, double sigma_mm,
    int draws = kLocalNoiseDraws);

// A frame's length noise, `draws` relative errors of its length.  Frame
// 0's a0 is set so that the model reaches from its apex to the highest data
// point (SpanAxialExtent) and is held afterwards, and an untracked later
// frame's base rim is held at its own highest points (SolveFrame's
// rim_height), so the noise of the few highest points moves the base rim,
// and with it every volume and the long axis's shortening, by an error no
// covariance of the free parameters holds (on the LV phantom's 400 tags
// EDV's interval held the noise-free fit in 53 % of draws; on its
// contours, shortening's in 77 % with frame 0's draws alone).  Each draw moves
// `model`'s points at the data's material points by noise of sd sigma_mm in
// every coordinate (as the data's heights are noisy) and reads TopHeight of
// them: (top(draw) - top) / (top - apex), top without noise.  Their mean is the
// bias the highest of many noisy points puts into the length.  Seeded by the
// frame's index.
std::vector<double> LengthNoiseDraws(const FramePoints& points,
                                     const std::vector<MaterialPoint>& material,
                                     const FitOptions& options,
                                     const Model& model, double sigma_mm,
                                     int draws = kLengthNoiseDraws);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_LOCAL_NOISE_H_
