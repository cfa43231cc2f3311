// Rows of one data point's residual and Jacobian, shared by the per-point
// and the grouped analytic residuals.  Internal to the library.
#ifndef PFDM_FIT_RESIDUALS_POINT_SAMPLE_ROWS_H_
#define PFDM_FIT_RESIDUALS_POINT_SAMPLE_ROWS_H_

#include <array>

#include "Eigen/Core"
#include "pfdm/fit/residuals/analytic_point_residual.h"
#include "pfdm/fit/residuals/free_entries.h"

namespace pfdm {
namespace internal {

constexpr int kBlockSizes[5] = {3, 4, kNumFunctions, kNumFunctions,
                                kNumFunctions};
// 0, 1, ..., kNumFunctions - 1.
struct FunctionIndices {
  int values[kNumFunctions];
  constexpr FunctionIndices() : values() {
    for (int i = 0; i < kNumFunctions; ++i) values[i] = i;
  }
};
inline constexpr FunctionIndices kFunctionIndices;
inline constexpr const int* kAllFunctions = kFunctionIndices.values;

// Whether `block` (0: the globals, 1 and 2: the two knots) supplies
// `function`: the globals supply the functions that are not free, the knots
// the free ones.
inline bool Supplies(int block, FunctionMask free_mask, int function) {
  const bool free = (free_mask >> function) & 1u;
  return free != (block == 0);
}

// d(R(q) s)/dq (3 x 4, row major) for R(q) s as UnitQuaternionRotatePoint
// computes it: s + 2w (v x s) + 2 v (v . s) - 2 s |v|^2.
void RotationJacobian(const double* q, const Eigen::Vector3d& s,
                      double* jacobian);

// The linear map s -> R(q) s of UnitQuaternionRotatePoint (R for unit q).
Eigen::Matrix3d RotationMatrix(const double* q);

// Where EvaluateSample writes a sample's Jacobian rows: per block the first
// row (null: not wanted) and the distance between rows; for the globals and
// the two knots, which functions their columns are.
struct RowLayout {
  double* first[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  int stride[5] = {3, 4, kNumFunctions, kNumFunctions, kNumFunctions};
  const int* functions[3] = {kAllFunctions, kAllFunctions, kAllFunctions};
  int width[3] = {kNumFunctions, kNumFunctions, kNumFunctions};

  // Each block's rows where Ceres wants them (row major, block wide).
  static RowLayout Blocks(double* const* jacobians, int row);
};

// The layout's functions and widths for blocks given as free entries.
RowLayout CompactLayout(const std::array<const FreeEntries*, 3>& entries);

// Writes one sample's residual rows and the Jacobian rows `layout` asks
// for.  parameters are the whole blocks.
void EvaluateSample(const PointSample& sample, FunctionMask free_mask,
                    bool unit_exponents, double const* const* parameters,
                    const Eigen::Matrix3d& rotation, double* residuals,
                    const RowLayout& layout);

}  // namespace internal
}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_POINT_SAMPLE_ROWS_H_
