// A tracked frame's residuals are not its tags' noise alone.  Through the
// wall a tag sits at the depth its rank gave it, which errs by about a
// tenth of the wall, along the wall's normal: on the LV phantom's 400 tags
// through the wall with 0.5 mm of noise the residual along the normal read
// 0.95 mm rms at ES (local field off, 10 seeds; with it 0.77 along and
// 0.51 across).
// That error is the sampling's, not the noise's: the same tags without
// noise left residuals of 0.95 mm along the normal, correlated 0.77 tag by
// tag with the noisy fit's.  One sigma for every coordinate (DataSigma)
// counted it as noise, and a tracked frame's share of a number's variance
// came out too large: over 100 noise draws the net twist's sd was 1.31
// times its error against the noise-free fit, torsion's 1.29 and the
// segments' thickening's 1.32, each interval holding it in 99-100 % of the
// draws.
//
// So on a solid's frame of tracked tags alone the data's rows are weighed by
// the residual's sd across the normal, s_t, where depths do not err:
//
//   C = A^+ (sigma^2 (A - D) + s_t^2 D) A^+ = sigma^2 A^+ + (s_t^2 - sigma^2)
//   A^+ D A^+,
//
// A = J'J of the whole problem, D = J_d'J_d of the data (three rows a
// point), sigma the pooled sd, which the regularizers' and gauges' rows
// keep; the sandwich of a least squares that weighed its rows alike.
// Held depths (FitOptions::hold_tag_depths, the default) err otherwise:
// a tracked frame's tag keeps the depth frame 0's noisy position gave it,
// an error of frame 0's noise that each draw redraws, not the sampling's.
// There the residual's variance along the normal exceeds the variance
// across it by that noise, e, and the rows along the normals take it:
//
//   C_held = C + e A^+ D_n A^+,
//
// D_n = sum_i J_i' n_i n_i' J_i (the added term kept apart too:
// FrameCovariance::depth_noise, part of which frame 0's model took up,
// report/tracked_response.h), e measured from neighbouring tags'
// residual differences (NeighbourNormalExcessMm2), which leave out a
// misfit the global model leaves smooth along the normal (a hypokinetic
// segment).  On the LV phantom's 400 tags through the wall (100 draws) the
// wall's thickening at ES had sd 3.41 against an rms error of 3.84 without
// it, its interval holding the noise-free fit in 0.90 of draws (0.89 with
// the lesion), 3.91 and 0.94 with it (0.95), GCS 0.92 -> 0.95 (0.90 ->
// 0.95).  Taken from the residuals' own sds (s_n^2 - s_t^2), which count
// the lesion's misfit, the lesion's intervals came out too wide (GCS and
// the volume fraction 0.99; docs/uncertainty.md).
//
// Frame 0's tags pull along their normals alone (their closest points are
// searched), so it keeps sigma: EDV's and the mass's intervals held the
// noise-free fit as promised with it (docs/uncertainty_calibration.md).
// Weighing the rows along the normal by their own sd instead widened ESV's
// and the ejection fraction's intervals to hold it in every draw; taking
// the frames' shared depth errors as correlated noise (the normal
// residuals' mean product over the tags both frames see, 0.43 mm^2) took
// the ejection fraction's to 0.90 and the thickening's to 0.83 (30 draws
// each; docs/uncertainty.md).  Only a solid's tags: on one surface a tag's
// depth is the surface's own, and its residual across the wall carries
// frame 0's tangential noise through its material point, which s_t would
// read as the frame's.
#ifndef PFDM_FIT_PROBLEM_DIRECTIONAL_NOISE_H_
#define PFDM_FIT_PROBLEM_DIRECTIONAL_NOISE_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/model/model.h"

namespace pfdm {

struct DirectionalSigma {
  double normal_mm = 0.0;   // Along n_i.
  double tangent_mm = 0.0;  // Each coordinate across it.
};

// The sds of the points' `residuals` at the model (Residuals) along and
// across `wall_normals` (unit), each point weighed by the robust loss as
// DataSigma weighs it; normal_parameters and tangent_parameters are each
// direction's share of the effective parameters.
DirectionalSigma DirectionalDataSigma(
    const std::vector<Eigen::Vector3d>& residuals,
    const std::vector<Eigen::Vector3d>& wall_normals, const std::string& loss,
    double loss_scale_mm, double normal_parameters, double tangent_parameters);

// C above over the first n columns: parts' matrices, the pooled sigma and
// the sd across the normals.
Eigen::MatrixXd DirectionalCovariance(const NormalParts& parts, int n,
                                      double sigma_mm, double tangent_mm);

// *covariance (BlockCovariance's, with `parts`; its sigma_mm the pooled
// sd, DataSigma's) made C above.  `normal_data_normal` is the data's J'J
// along the normals, sum_i J_i' n_i n_i' J_i over parts' columns: its
// share tr(A^+ D_n) of the effective parameters is the normal's, and with
// `depths_held` the rows along the normals take the neighbours' excess e
// too (C_held above).  Sets
// normal_sigma_mm and tangent_sigma_mm.
void ScaleByDirectionalNoise(const NormalParts& parts,
                             const Eigen::MatrixXd& normal_data_normal,
                             const Model& model,
                             const std::vector<Eigen::Vector3d>& points,
                             const std::vector<MaterialPoint>& material,
                             const std::vector<Eigen::Vector3d>& wall_normals,
                             const std::string& loss, double loss_scale_mm,
                             bool depths_held, FrameCovariance* covariance);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_DIRECTIONAL_NOISE_H_
