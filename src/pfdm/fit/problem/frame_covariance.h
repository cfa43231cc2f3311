// How sure a frame's global fit is of its parameters: their covariance at
// the solution, the Gauss-Newton one, sigma^2 (J'J)^+, J the Jacobian of
// every residual of the frame's problem (data, smoothness, rim, gauges,
// prior) and sigma^2 the data's residual variance the fit measures (on a
// solid's frame of tracked tags alone, the data's rows weighed by the
// residual's variance across the wall instead: directional_noise.h).
//
// Every residual of the problem is a length in mm with its weight, so the
// regularizers enter as what they are, Gaussian priors whose strength
// relative to the data the fit's weights set; the gauge residuals (weight
// 10 sqrt(N)) act as constraints, and held entries are not parameters at
// all (their standard deviation is 0, by definition of the gauge).
//
// What it is conditional on (docs/uncertainty.md).  Contours' (and frame
// 0's tags') closest points are re-found every round: at the solution the
// residual is normal to the surface, so the distance's derivative with
// respect to the parameters is the point-to-plane residual's, and
// minimizing over the correspondences leaves the same Gauss-Newton matrix
// to first order (a variable projection; checked by sampling in
// LvUncertaintyCalibrationTest's contour case).  Tracked frames' material
// points, found on frame 0 from noisy tags, are held: their per-point error
// shows in sigma, frame 0's shared error does not (its length's part, the
// top's and the apex's, is added to a3's reported sd: io/fit_output.h
// ReportedSd).  Held too: the prior's target (the previous frame), a
// solid's tag depths w, and the local field, fitted after this.
#ifndef PFDM_FIT_PROBLEM_FRAME_COVARIANCE_H_
#define PFDM_FIT_PROBLEM_FRAME_COVARIANCE_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "ceres/ceres.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// One coordinate of the covariance: an entry of the globals or of a knot,
// or one of the pose's (the centre's x, y, z; the rotation's three tangent
// directions, ceres::QuaternionManifold's, radians about the world axes
// applied on the left).
struct CovarianceEntry {
  enum class Kind { kCenter, kRotation, kGlobal, kKnot };
  Kind kind = Kind::kKnot;
  int knot = -1;     // kKnot only.
  int function = 0;  // The function (kGlobal, kKnot) or the axis (pose).
  std::string Name() const;  // "center_x", "rotation_z", "a0", "tau[3]".
};

struct FrameCovariance {
  // False when not computed (--uncertainty off) or when Ceres could not.
  bool computed = false;
  // The data's residual standard deviation per residual coordinate (mm):
  // sqrt(sum_i w_i |r_i|^2 / (sum_i w_i d_i - n)), r_i point i's residual
  // (its distance along the normal for a point-to-plane one, d_i = 1, else
  // the vector, d_i = 3), w_i the robust loss's weight (1 without a loss),
  // n the free parameters' effective number (effective_parameters).
  double sigma_mm = 0.0;
  double degrees_of_freedom = 0.0;
  // On a solid's frame of tracked tags alone (three residual rows a
  // point), the residual's sd along each tag's wall normal and across it,
  // each coordinate's; the data's rows are weighed by the one across
  // (directional_noise.h).  0 elsewhere, where sigma_mm weighs them.
  double normal_sigma_mm = 0.0;
  double tangent_sigma_mm = 0.0;
  // The data's noise the covariance is scaled by: tangent_sigma_mm where
  // measured, else sigma_mm.
  double NoiseSigma() const {
    return tangent_sigma_mm > 0.0 ? tangent_sigma_mm : sigma_mm;
  }
  // n above: the trace of the data's hat matrix, tr((J'J)^+ J_d'J_d), J_d
  // the data's rows.  The regularizers and the gauge take part of the
  // parameters' freedom, so it is less than their count: dividing by the
  // count's degrees of freedom overstated sigma by up to 15 % on a frame of
  // 150 sliding points and 74 parameters (intervals too wide, and
  // narrowing faster than 1/sqrt(N) as points were added).
  double effective_parameters = 0.0;
  // The directions of J'J (scaled to a unit diagonal) under
  // kMinReciprocalCondition times its largest eigenvalue that lie mostly in
  // these parameters, left out of the
  // pseudo-inverse: what the problem does not determine.  Each is named by
  // its largest entries.
  int rank_deficiency = 0;
  std::vector<std::string> deficient_directions;
  // The free coordinates, in the order of `covariance`'s rows: the pose
  // (when free), the globals' free entries, then each knot's, ascending.
  std::vector<CovarianceEntry> entries;
  Eigen::MatrixXd covariance;
  // (J'J)^+ over `entries`: the covariance at unit sigma, and the least
  // squares' response to a change of its data, -(J'J)^+ J'dr (report/
  // tracked_response.h).  Empty where not computed.
  Eigen::MatrixXd unit_covariance;
  // The part of `covariance` that held depths' noise adds, e A^+ D_n A^+
  // (directional_noise.h): frame 0's noise, which also moved frame 0's
  // model (report/tracked_response.h).  Empty elsewhere.
  Eigen::MatrixXd depth_noise;
  double seconds = 0.0;  // What computing it took.
  // The local field, fitted after this, is not in `covariance`: these are
  // draws of the field the frame's noise alone fits (fit/stages/
  // local_noise.h), each LocalField::values' layout; empty without a field.
  std::vector<std::vector<double>> local_noise;
  // Draws of the length's relative error that the noise of the frame's
  // highest points puts into the reference frame's held a0, or into an
  // untracked later frame's base rim (fit/stages/local_noise.h,
  // LengthNoiseDraws); empty on tracked frames.
  std::vector<double> length_noise;
  // The reference frame's other end: its length is the top less the fitted
  // apex, and with a0 held the covariance moves the apex only with the
  // centre, along the axis, never the length.  The apex's variance along
  // the axis (ApexAxialVariance) over the squared length; 0 elsewhere.
  double apex_length_variance = 0.0;
  // The draws' mean (0 without draws), the length's bias; and the length's
  // relative variance: the draws' sample variance (0 with fewer than two)
  // plus the apex's.
  double LengthNoiseMean() const;
  double LengthNoiseVariance() const;

  // Index of (kind, knot, function) in entries, or -1 (held, or absent).
  int IndexOf(CovarianceEntry::Kind kind, int knot, int function) const;
  // Index in entries of function f's value at knot k: its knot entry for a
  // free function, its global for a constant one; -1 when held or fixed.
  int FunctionIndex(const ModelConfig& config, int f, int k) const;
  // Standard deviation of function f's value at knot k in the model's own
  // units (a1..a3 relative to a0): its knot entry's for a free function,
  // its global's for a constant one; 0 for a held or fixed one.
  double KnotSd(const ModelConfig& config, int f, int k) const;
};

// The variance (mm^2) of `model`'s apex along its long axis: the centre's
// covariance along the axis.  The apex sits on the axis, so the pose's
// rotation moves it across the axis alone (to first order), and frame 0's
// a0 and a3, which place it from the centre, are held.  0 when the centre
// is not free.  On the LV phantom's contours (20 draws) it read 0.165,
// 0.203 and 0.247 mm on the endocardium, mid-wall and epicardium against
// the apex's errors of 0.136, 0.251 and 0.355 mm; 0.158 against 0.154 on
// mid-wall tags.
double ApexAxialVariance(const FrameCovariance& covariance, const Model& model);

// Keeps the eigen-directions of J'J at least this fraction of its largest.
inline constexpr double kMinReciprocalCondition = 1e-10;

// A parameter block of the problem and what its coordinates are.
struct CovarianceBlock {
  const double* parameters = nullptr;
  std::vector<CovarianceEntry> entries;  // One per tangent coordinate.
};

// The covariance of `blocks` (non-constant blocks of `problem`, at their
// current values): the pseudo-inverse of J'J over every free block of the
// problem (as ceres::Covariance's DENSE_SVD with null_space_rank -1 would
// give it, which tolerates a rank deficiency: the deficient directions are
// left out and reported), its rows and columns of `blocks` kept, times
// sigma_mm^2.  J'J is scaled to a unit diagonal first, so that the gauge's
// stiff weights do not count as ill-conditioning; the cut is on the scaled
// matrix's eigenvalues.  The loss, when the residuals have one, weighs them
// as the solve did.  `data`: the data's residual blocks, the problem's
// first, for effective_parameters.  computed false when the problem cannot
// be evaluated.
//
// `parts`, when given, gets the unscaled (J'J)^+ and J_d'J_d over every
// free column (ColumnOrder's: `blocks` first), for a caller that weighs the
// data's rows unlike sigma_mm^2 alike (directional_noise.h).
struct NormalParts {
  Eigen::MatrixXd pseudo_inverse;  // (J'J)^+.
  Eigen::MatrixXd data_normal;     // J_d'J_d.
};
FrameCovariance BlockCovariance(
    ceres::Problem* problem, const std::vector<CovarianceBlock>& blocks,
    double sigma_mm, double degrees_of_freedom,
    const std::vector<ceres::ResidualBlockId>& data = {},
    NormalParts* parts = nullptr);

// J_d'J_d of `problem`'s data rows (`data`, its first residual blocks)
// over ColumnOrder(problem, blocks); empty when the problem cannot be
// evaluated.
Eigen::MatrixXd DataNormalMatrix(
    ceres::Problem* problem, const std::vector<CovarianceBlock>& blocks,
    const std::vector<ceres::ResidualBlockId>& data);

// The data's residual standard deviation at the model (FrameCovariance::
// sigma_mm) and its degrees of freedom, for num_parameters free
// parameters (effective_parameters).  normals as SolveFrame's; loss and
// scale as the fit's.
void DataSigma(const Model& model, const std::vector<Eigen::Vector3d>& points,
               const std::vector<MaterialPoint>& material,
               const std::vector<Eigen::Vector3d>& normals,
               const std::string& loss, double loss_scale_mm,
               double num_parameters, double* sigma_mm,
               double* degrees_of_freedom);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_FRAME_COVARIANCE_H_
