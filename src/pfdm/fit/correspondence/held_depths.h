// A solid's tags keep frame 0's depth w across the wall in every later
// frame, as they keep frame 0's (u, v): a tag's place across the wall is
// material (docs/gauge.md, "Depths held from frame 0").
//
// Ranked anew in every frame, a tag's depth took up whatever the frame's
// ranks made of its motion: a segment thickening less than its ring had its
// tags spread over the same ranks, and on the LV phantom (3,000 tags
// through the wall, no noise) the ranks' sampling read the basal segments'
// thickening 5 points high and the mid ones' 4.5 low.
//
// Held from frame 0's noisy distances, a depth regresses to the mean: the
// tags frame 0's noise put outermost lie inside the wall the depth says
// they bound, and every later frame's wall read 5-6 % thin (the LV
// phantom and the cylindrical wall segment, 0.5 mm of noise).  So the held
// depth is the depth's expectation given frame 0's distance, w's spread
// through the wall being uniform and the noise Gaussian.  Against it the
// later frames' thickness is unbiased (the expectation's regression
// property, E[w | w_hat] = w_hat), and needs no deconvolution.
#ifndef PFDM_FIT_CORRESPONDENCE_HELD_DEPTHS_H_
#define PFDM_FIT_CORRESPONDENCE_HELD_DEPTHS_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// E[w | w_obs] for w uniform on [-1, 1] and w_obs - w ~ N(0, s^2): the mean
// of N(w_obs, s^2) truncated to [-1, 1],
//
//   w_obs + s (phi(a) - phi(b)) / (Phi(b) - Phi(a)),
//   a = (-1 - w_obs) / s,  b = (1 - w_obs) / s.
//
// Within [-1, 1], odd in w_obs, increasing; w_obs clamped to [-1, 1] at
// s = 0.  Past 8 s outside the wall it is taken at 8 s (within s / 8 of
// the wall), where Phi(b) - Phi(a) would underflow.
double ShrunkDepth(double w_obs, double s);

// Each tag's material point held from `reference` (frame 0's global model,
// its layers evenly spaced: k(w) = w h / 2), starting from `material` (its
// ranked one): the layer w_fit and the (u, v) on it where the tag lies
// (kInversePasses of a closest-point search on the layer and a step of w
// along its normal), and the depth a ShrunkDepth(w_obs / a, s / a), w_obs =
// w_fit h_fit / h, s = 2 sigma_mm / h, h the thickness at its u with noise
// of sigma_mm taken out (DeconvolvedThickness: frame 0's h_fit comes from
// ranks).  The (u, v) of the tag's own layer, not of its rank's, which on
// a tilted wall sits elsewhere along it.  a is the half-width of the
// uniform the tags fill, 3 (mean w_obs^2 - mean s^2) under a root, not 1:
// frame 0's h errs by a few percent from draw to draw, and a prior of the
// wrong width shrinks the outer tags too much or too little (on the wall
// segments' eight draws of 3,000 tags, with a = 1, the thickening's mean
// error 0.4-1.0 points and 3.22 at worst; with a, 1.008-1.018 there,
// -1.06 to -0.41 and 2.68, sigma from neighbouring tags' residuals,
// wall_stage.h).  Without noise (sigma_mm 0) a is 1.
std::vector<MaterialPoint> HeldMaterialPoints(
    const Model& reference, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material, double sigma_mm);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_HELD_DEPTHS_H_
