// How sure a frame's global fit is of its parameters: their covariance at
// the solution, the Gauss-Newton one, sigma^2 (J'J)^+, J the Jacobian of
// every residual of the frame's problem (data, smoothness, rim, gauges,
// prior) and sigma^2 the data's residual variance the fit measures.
//
// Every residual of the problem is a length in mm with its weight, so the
// regularizers enter as what they are, Gaussian priors whose strength
// relative to the data the fit's weights set; the gauge residuals (weight
// 10 sqrt(N)) act as constraints, and held entries are not parameters at
// all (their standard deviation is 0, by definition of the gauge).
//
// What it is conditional on: the frame's material points.  Tags keep
// theirs, but contours' (and on frame 0 the tags') closest points are
// re-found every round, and the covariance treats the final ones as known.
// A point's closest point slides with the surface, so its pull along the
// normal, the only one contours give, is what a fixed correspondence gives
// too to first order; what is left out is that the correspondences were
// chosen from the noisy data themselves, which makes these intervals
// somewhat too narrow for contours (a sandwich estimate or resampling would
// take it in: issue 30).  The prior's target (the previous frame) is taken
// as known too, so uncertainty is not carried from frame to frame.
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
  // n the number of free parameters.
  double sigma_mm = 0.0;
  double degrees_of_freedom = 0.0;
  // The directions of J'J under kMinReciprocalCondition times its largest
  // eigenvalue that lie mostly in these parameters, left out of the
  // pseudo-inverse: what the problem does not determine.  Each is named by
  // its largest entries.
  int rank_deficiency = 0;
  std::vector<std::string> deficient_directions;
  // The free coordinates, in the order of `covariance`'s rows: the pose
  // (when free), the globals' free entries, then each knot's, ascending.
  std::vector<CovarianceEntry> entries;
  Eigen::MatrixXd covariance;
  double seconds = 0.0;  // What computing it took.

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
// sigma_mm^2.  The loss, when the residuals have one, weighs them as the
// solve did.  computed false when the problem cannot be evaluated.
FrameCovariance BlockCovariance(ceres::Problem* problem,
                                const std::vector<CovarianceBlock>& blocks,
                                double sigma_mm, double degrees_of_freedom);

// The data's residual standard deviation at the model (FrameCovariance::
// sigma_mm) and its degrees of freedom, for num_parameters free
// parameters.  normals as SolveFrame's; loss and scale as the fit's.
void DataSigma(const Model& model, const std::vector<Eigen::Vector3d>& points,
               const std::vector<MaterialPoint>& material,
               const std::vector<Eigen::Vector3d>& normals,
               const std::string& loss, double loss_scale_mm,
               int num_parameters, double* sigma_mm,
               double* degrees_of_freedom);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_FRAME_COVARIANCE_H_
