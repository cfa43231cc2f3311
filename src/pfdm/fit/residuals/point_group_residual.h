// Many data points as one residual block, in square-root form.
#ifndef PFDM_FIT_RESIDUALS_POINT_GROUP_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_POINT_GROUP_RESIDUAL_H_

#include <array>
#include <vector>

#include "ceres/cost_function.h"
#include "pfdm/fit/residuals/analytic_point_residual.h"
#include "pfdm/fit/residuals/free_entries.h"
#include "pfdm/fit/residuals/square_root_form.h"

namespace pfdm {

// Many points between the same two knots as one residual block, their
// residuals stacked.  Ceres then handles a few tall blocks instead of
// thousands of 3-row ones.  A robust loss acts per block, so with one the
// fitter gives each point a group of its own.
//
// The blocks are as the frame's problem holds them: the globals and the two
// knots as their free entries (entries[i]; null: the whole block), and
// `varied` says which of the five blocks the solve moves.  When the group
// has more rows than the varied blocks have columns (n), it gives Ceres its
// square-root form (square_root_form.h): residual (z, rho), Jacobian (R; 0),
// n + 1 rows with the same cost, gradient and J^T J as its 3 rows per
// point.  Evaluated without Jacobians it gives (|r|, 0, ..., 0): the same
// cost again.  Jacobians of blocks not in `varied` cannot be asked for then.
// When both knots are varied over the same functions, J^T J is summed from
// small per-point moments in the model frame, without forming J, the
// pose's columns included when every point has three rows
// (docs/jacobians.md, "The Gram matrix without J").
class PointGroupResidual : public ceres::CostFunction {
 public:
  PointGroupResidual(std::vector<PointSample> samples, FunctionMask free_mask,
                     bool unit_exponents,
                     std::array<const FreeEntries*, 3> entries = {},
                     std::array<bool, 5> varied = {true, true, true, true,
                                                   true});
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;
  bool compressed() const { return compressed_; }
  int num_samples() const { return static_cast<int>(samples_.size()); }

  // Computes the square-root form (with_jacobians) or the residual norm at
  // `parameters` ahead of Ceres, for Evaluate to hand out while it is asked
  // at the same parameter values (PrecomputedGroups), the form also when
  // asked without Jacobians.  Returns the squared residual norm (0 for a
  // group too small to compress, which computes on demand).  Not
  // thread-safe against Evaluate; Ceres calls neither during the other.
  double Precompute(double const* const* parameters, bool with_jacobians) const;

 private:
  // What a compressed group hands Ceres at one set of parameter values.
  struct Result {
    // The parameter values, block after block (Precompute's only).
    std::vector<double> at;
    bool with_jacobians = false;
    double norm = 0.0;    // |r|, with Jacobians or without.
    SquareRootForm form;  // With.
  };
  // The globals and knots whole, from their free entries (into `whole`).
  void WholeBlocks(double const* const* parameters, FunctionValues whole[3],
                   const double* blocks[5]) const;
  Result Compute(double const* const* parameters, bool with_jacobians) const;
  void Write(const Result& result, double* residuals, double** jacobians) const;
  bool IsAt(const Result& result, double const* const* parameters) const;

  double ResidualNorm(const double* const* blocks,
                      const Eigen::Matrix3d& rotation) const;
  RowMajorMatrix StackedRows(const double* const* blocks,
                             const Eigen::Matrix3d& rotation) const;
  Eigen::MatrixXd MomentGram(const double* const* blocks,
                             const Eigen::Matrix3d& rotation) const;
  Eigen::MatrixXd PoseMomentGram(const double* const* blocks,
                                 const Eigen::Matrix3d& rotation) const;

  std::vector<PointSample> samples_;
  FunctionMask free_mask_;
  bool unit_exponents_;
  std::array<const FreeEntries*, 3> entries_;
  std::array<bool, 5> varied_;
  int widths_[5];   // Parameter block sizes.
  int offsets_[5];  // First column of each varied block in J.
  int columns_ = 0;
  int rows_ = 0;
  bool compressed_ = false;
  bool knots_alike_ = false;  // Both knots varied, over the same functions.
  // Knots alike, the pose varied, the globals held and no point-to-plane
  // sample (a tracked frame): the pose's columns come from moments of s.
  bool pose_moments_ = false;
  mutable Result precomputed_;  // Empty `at` until Precompute.
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_POINT_GROUP_RESIDUAL_H_
