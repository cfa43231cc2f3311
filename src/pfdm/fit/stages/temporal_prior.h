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
// --temporal_prior), relative to one knot's share of the data as the other
// priors' weights (untracked_prior_weight, 0.01).  On biv-me patient 1's
// contours (pfdm fit --contours lv-cavity, 25 frames) 0.05 ends the rounds
// of every frame settled (3 frames ran out without it; 0.03 leaves one at
// 0.10 mm) in 170 rounds and 574 solver iterations (287 and 1,194 without;
// 228 and 924 before the rounds were mixed), pooled RMS 0.781 mm (0.775),
// and the largest level strain spike is 9.3 points (14.0).  A stronger pull
// lags the motion: on the LV phantom's 9-frame cycle seen as short-axis
// contours (testing/lv_temporal_prior_test.cc) 0.05 moves end-systole's
// radial contraction by -0.8 points and longitudinal shortening by -1.4;
// 0.1 by -1.7 and -3.1, while biv-me's spike still read 8.5 (1.0: 8.5,
// RMS 0.91 mm).  Off by default: at frame 1 the previous frame is frame 0,
// so the pull only pulls harder toward frame 0, and a moving phantom's
// contours (FitterTest) then took 15 rounds at 0.02 and 20 at 0.05 where
// they settle in under 10; and without the landmarks' axis (the
// library's default options) biv-me's frame 24 no longer came back to frame 0's
// basal radii within 10 % (0.89 and 1.14 at the base knot).
inline constexpr double kSuggestedTemporalPriorWeight = 0.05;

struct FramePrior {
  ModelState state;  // The target; its pose is not pulled.
  // The options the frame is solved with: for an untracked frame with a
  // temporal weight, untracked_prior_weight is the summed weight.
  FitOptions options;
};

// Tracked and reference frames: `previous` with the options as they are.
// Untracked frames: frame 0's state (`reference`), mixed with `previous`
// by options.temporal_prior_weight (above; 0: frame 0's alone).
FramePrior PriorOfFrame(FrameKind kind, const ModelState& reference,
                        const ModelState& previous, const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_TEMPORAL_PRIOR_H_
