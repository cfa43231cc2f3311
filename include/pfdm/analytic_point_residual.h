// The data residuals of point_residual.h with hand-derived Jacobians,
// following the paper's chain xdot = [I  B  R J] qdot.
#ifndef PFDM_ANALYTIC_POINT_RESIDUAL_H_
#define PFDM_ANALYTIC_POINT_RESIDUAL_H_

#include <array>
#include <vector>

#include "ceres/cost_function.h"
#include "ceres/sized_cost_function.h"
#include "pfdm/free_entries.h"
#include "pfdm/model_point.h"
#include "pfdm/square_root_form.h"

namespace pfdm {

// One data point tied to its material point.  With a normal it gives the
// point-to-plane residual n . (x - d), else the 3-vector x - d.
struct PointSample {
  Eigen::Vector3d data = Eigen::Vector3d::Zero();
  Angles<double> angles{1.0, 0.0, 1.0, 0.0};
  double knot_weight = 0.0;
  bool has_normal = false;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();

  PointSample() = default;
  PointSample(const Eigen::Vector3d& data, double u, double v,
              double knot_weight);
  PointSample(const Eigen::Vector3d& data, double u, double v,
              double knot_weight, const Eigen::Vector3d& normal);
  int num_residuals() const { return has_normal ? 1 : 3; }
};

// Writes the sample's residual rows and, for each block asked for (non-null
// in jacobians), its Jacobian rows, row major.
void EvaluatePointSample(const PointSample& sample, FunctionMask free_mask,
                         bool unit_exponents, double const* const* parameters,
                         double* residuals, double** jacobians);

// Parameter blocks of every data residual: center (3), quaternion (4),
// globals, knot0, knot1 (kNumFunctions each).  With x = c + R(q) s(f):
//   dr/dc = I,
//   dr/dq = d(R(q) s)/dq for the ambient quaternion (w, v), as
//           UnitQuaternionRotatePoint evaluates R s = s + 2w v x s
//           + 2 v (v . s) - 2 s |v|^2,
//   dr/d(globals, knot0, knot1) = R ds/df times 1, (1 - w) or w on the
//           functions each block supplies (docs/jacobians.md),
// and n^T times all of that for a point-to-plane sample.
template <int kNumResiduals>
class AnalyticResidual
    : public ceres::SizedCostFunction<kNumResiduals, 3, 4, kNumFunctions,
                                      kNumFunctions, kNumFunctions> {
 public:
  AnalyticResidual(const PointSample& sample, FunctionMask free_mask,
                   bool unit_exponents)
      : sample_(sample),
        free_mask_(free_mask),
        unit_exponents_(unit_exponents) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    EvaluatePointSample(sample_, free_mask_, unit_exponents_, parameters,
                        residuals, jacobians);
    return true;
  }

 private:
  PointSample sample_;
  FunctionMask free_mask_;
  bool unit_exponents_;
};

using AnalyticPointResidual = AnalyticResidual<3>;    // Without a normal.
using AnalyticSurfaceResidual = AnalyticResidual<1>;  // With a normal.

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
// small per-point moments in the model frame, without forming J
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

 private:
  double ResidualNorm(const double* const* blocks,
                      const Eigen::Matrix3d& rotation) const;
  RowMajorMatrix StackedRows(const double* const* blocks,
                             const Eigen::Matrix3d& rotation) const;
  Eigen::MatrixXd MomentGram(const double* const* blocks,
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
};

}  // namespace pfdm

#endif  // PFDM_ANALYTIC_POINT_RESIDUAL_H_
