// The tags' localization noise from neighbouring tags' residuals, for held
// depths (held_depths.h), which read the model's misfit as noise otherwise.
//
// TangentialNoiseMm (transmural.h) takes every tangential residual for
// noise: a global model's smooth misfit too, which read 0.15-0.21 mm of
// "noise" on the LV phantom's noise-free tags through the wall (400 tags),
// shrank their held depths toward the mid-wall and read the noise-free
// fit's thickening high.  Two tags a few millimetres apart share the smooth
// misfit and not their noise, so the difference of their residuals is the
// noise's: 0.10-0.11 mm there, 0.50-0.55 with 0.5 mm of noise (the
// misfit's 0.1 in quadrature), frame 0's share read as stretched.
#ifndef PFDM_FIT_CORRESPONDENCE_NEIGHBOUR_NOISE_H_
#define PFDM_FIT_CORRESPONDENCE_NEIGHBOUR_NOISE_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Localization noise (mm per coordinate, isotropic) of tracked tags
// `which`, at `positions` with `residuals` on `model`: for each tag i its
// nearest tag j (by position), d = the part of r_i - r_j across n_i, the
// normal of i's layer.  Each tangential component of a residual carries
// this frame's noise and frame 0's (through the tag's (u, v)), variance
// 2 sigma^2, the difference 4 sigma^2, so |d|^2 is 4 sigma^2 times a
// chi-squared of 2 degrees of freedom:
//
//   sigma^2 = mean |d|^2 / 8,   robust: median |d|^2 / (8 ln 2).
//
// That holds where the wall has not moved since frame 0.  Given each
// tag's stretch_squared (|F|^2 from frame 0, tangential_stretch.h; indexed
// like `which`), frame 0's share is stretched: |d|^2 carries
// sigma^2 (4 + |F_i|^2 + |F_j|^2), and each is scaled by 8 over that.
// Without it, a systolic frame's contraction read 0.5 mm of noise on the
// LV phantom at end-systole as 0.45-0.50 (0.47 on average), and the held
// depths, shrunk too little, read thickening 1.5 points low.
// 0 for fewer than two tags.
double NeighbourTangentialNoiseMm(
    const Model& model, const std::vector<Eigen::Vector3d>& positions,
    const std::vector<Eigen::Vector3d>& residuals,
    const std::vector<MaterialPoint>& material,
    const std::vector<size_t>& which, bool robust = false,
    const std::vector<double>* stretch_squared = nullptr);

// How much more the residuals of tags at `positions` vary along the
// `normals` of their layers (unit) than across them (mm^2), from the same
// differences of
// nearest tags, which leave a smooth misfit out (a regional defect the
// global model cannot follow, along the normal): with d = r_i - r_j, the
// normal's variance is mean (n_i . d)^2 / 2 and a tangential coordinate's
// mean |d - (n_i . d) n_i|^2 / 4, and the excess is the first less the
// second.  Held depths (held_depths.h) put frame 0's noise into a tracked
// frame's residuals along the normal (directional_noise.h).  0 for fewer
// than two tags; may be negative.
double NeighbourNormalExcessMm2(const std::vector<Eigen::Vector3d>& positions,
                                const std::vector<Eigen::Vector3d>& residuals,
                                const std::vector<Eigen::Vector3d>& normals);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_NEIGHBOUR_NOISE_H_
