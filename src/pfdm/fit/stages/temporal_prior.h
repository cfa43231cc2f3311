// The state a frame's prior pulls toward, and how hard.  A frame without
// tracked points is pulled toward frame 0's state (untracked_prior_weight)
// and toward the frame before it (--temporal_prior): its contours fix the
// surface but leave it free to jump from frame to frame along what they
// see little of (the base, the outflow tract), and each jump moves the
// closest points the next rounds search for; strain, measured on material
// points against frame 0, reads the jumps as a measurement.
//
// Two quadratic pulls that share their scales (FunctionScales, the same
// model's) are one pull of the summed weight toward the weighted mean of
// their targets, up to a constant:
//   w0 |S (x - a)|^2 + w1 |S (x - b)|^2
//     = (w0 + w1) |S (x - (w0 a + w1 b) / (w0 + w1))|^2 + const,
// so the frame's problem keeps its one prior term.
#ifndef PFDM_FIT_STAGES_TEMPORAL_PRIOR_H_
#define PFDM_FIT_STAGES_TEMPORAL_PRIOR_H_

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/model/model.h"

namespace pfdm {

// A pull toward the previous frame (FitOptions::temporal_prior_weight,
// --temporal_prior, 0.05 by default), relative to one knot's share of the
// data as the other priors' weights (untracked_prior_weight, 0.01).  On
// biv-me patient 1's contours (pfdm fit --contours lv-cavity, 25 frames,
// the outflow-tract rings left out: io/partial_rings.h) it ends the rounds
// of every frame settled (4 frames ran out by 0.10-0.14 mm without it) in
// 163-166 rounds (274 without), pooled RMS 0.76-0.77 mm, and no level's
// Ecc or Ell departs from its neighbours' mean by 3 points (4.9 without).
// A stronger pull lags the motion: on the LV phantom's 9-frame cycle seen
// as short-axis contours 0.05 moved end-systole's radial contraction by
// -0.8 points and longitudinal shortening by -1.4, 0.1 by -1.7 and -3.1
// (docs/contour_sequences.md).  Without the landmarks' axis (the library's
// default options) biv-me's frame 24 comes back to frame 0's radii at the
// top knot within 11-14 % (5-7 % without the pull).
inline constexpr double kSuggestedTemporalPriorWeight = 0.05;

// The pull assumes a frame lies close to the one before, as a cine's 20-30
// frames a cycle do.  A sequence of fewer frames moves further between
// them, and the pull lags: on the LV phantom's 9-frame cycle as contours
// it read end-systole's longitudinal shortening 13.6 % against 17.0 true
// (3.4 points under; 0.9 under without it), and a 10-frame mask phantom's
// end-systolic cavity 5.7 % over its voxels.  Shorter sequences are
// fitted without it (SequenceFit::temporal_prior_weight records what was
// used).
inline constexpr int kTemporalPriorMinFrames = 20;

// options.temporal_prior_weight for a sequence of `num_frames`, 0 below
// kTemporalPriorMinFrames.
double TemporalPriorWeightFor(int num_frames, const FitOptions& options);

struct FramePrior {
  ModelState state;  // The target; its pose is not pulled.
  // The options the frame is solved with: for an untracked frame with a
  // temporal weight, untracked_prior_weight is the summed weight.
  FitOptions options;
};

// Tracked and reference frames: `previous` with the options as they are.
// Untracked frames: frame 0's state (`reference`), mixed with `previous`
// by options.temporal_prior_weight (above; 0: frame 0's alone).  The
// frame after frame 0 (previous_is_reference) keeps frame 0's pull alone:
// its previous frame is frame 0, so the temporal weight would only make
// that pull stronger, and a moving phantom's contours then took 15-20
// rounds at frame 1 where they settle in under 10
// (FitterTest.FramesSayWhenTheirClosestPointsHaveNotSettled).
FramePrior PriorOfFrame(FrameKind kind, const ModelState& reference,
                        const ModelState& previous, bool previous_is_reference,
                        const FitOptions& options);

// A correspondence round's pull toward the state it starts from, mixed
// into the frame's prior as above (`prior` toward `start`, `weight` added
// to the weight of the frame's kind: untracked_prior_weight for an
// untracked frame, prior_weight otherwise).  GlobalRounds uses it where
// rounds swing back and forth (global_rounds.cc, kSwingCosine).
FramePrior PulledTowardStart(FrameKind kind, const ModelState& prior,
                             const FitOptions& options, const ModelState& start,
                             double weight);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_TEMPORAL_PRIOR_H_
