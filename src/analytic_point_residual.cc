#include "pfdm/analytic_point_residual.h"

#include <algorithm>

#include "Eigen/Geometry"
#include "pfdm/shape_jacobian.h"

namespace pfdm {
namespace {

constexpr int kBlockSizes[5] = {3, 4, kNumFunctions, kNumFunctions,
                                kNumFunctions};

using RowMajor3xN = Eigen::Matrix<double, 3, kNumFunctions, Eigen::RowMajor>;

// d(R(q) s)/dq (3 x 4, row major) for R(q) s as UnitQuaternionRotatePoint
// computes it: s + 2w (v x s) + 2 v (v . s) - 2 s |v|^2.
void RotationJacobian(const double* q, const Eigen::Vector3d& s,
                      double* jacobian) {
  const double w = q[0];
  const Eigen::Vector3d v(q[1], q[2], q[3]);
  Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> j(jacobian);
  j.col(0) = 2.0 * v.cross(s);
  Eigen::Matrix3d skew_s;
  skew_s << 0, -s.z(), s.y(), s.z(), 0, -s.x(), -s.y(), s.x(), 0;
  j.rightCols<3>() = -2.0 * w * skew_s +
                     2.0 * v.dot(s) * Eigen::Matrix3d::Identity() +
                     2.0 * v * s.transpose() - 4.0 * s * v.transpose();
}

// The linear map s -> R(q) s of UnitQuaternionRotatePoint (R for unit q).
Eigen::Matrix3d RotationMatrix(const double* q) {
  const double w = q[0];
  const Eigen::Vector3d v(q[1], q[2], q[3]);
  Eigen::Matrix3d skew_v;
  skew_v << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return (1.0 - 2.0 * v.squaredNorm()) * Eigen::Matrix3d::Identity() +
         2.0 * w * skew_v + 2.0 * v * v.transpose();
}

// Writes one sample's residual rows and, for each block asked for, its
// Jacobian rows starting at jacobians[i] (row major, block-wide rows).
void EvaluateSample(const PointSample& sample, FunctionMask free_mask,
                    bool unit_exponents, double const* const* parameters,
                    const Eigen::Matrix3d& rotation, double* residuals,
                    double* const* jacobians) {
  double f[kNumFunctions];
  InterpolateFunctions(free_mask, parameters[2], parameters[3], parameters[4],
                       sample.knot_weight, f);
  bool want[5] = {false, false, false, false, false};
  bool want_shape_jacobian = false;
  for (int i = 0; jacobians != nullptr && i < 5; ++i) {
    want[i] = jacobians[i] != nullptr;
    want_shape_jacobian = want_shape_jacobian || (i >= 2 && want[i]);
  }
  ShapeJacobian shape_jacobian;
  const Eigen::Vector3d s =
      ShapeAndJacobian(f, sample.angles, unit_exponents,
                       want_shape_jacobian ? &shape_jacobian : nullptr);
  const Eigen::Vector3d residual =
      rotation * s + Eigen::Map<const Eigen::Vector3d>(parameters[0]) -
      sample.data;
  if (sample.has_normal) {
    residuals[0] = sample.normal.dot(residual);
  } else {
    std::copy(residual.data(), residual.data() + 3, residuals);
  }
  if (jacobians == nullptr) return;

  // The 3-row Jacobians of x, projected on the normal when there is one.
  double rows[3 * kNumFunctions];
  auto emit = [&](int block) {
    const int width = kBlockSizes[block];
    if (!sample.has_normal) {
      std::copy(rows, rows + 3 * width, jacobians[block]);
      return;
    }
    for (int c = 0; c < width; ++c) {
      jacobians[block][c] = sample.normal[0] * rows[c] +
                            sample.normal[1] * rows[width + c] +
                            sample.normal[2] * rows[2 * width + c];
    }
  };
  if (want[0]) {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rows)
        .setIdentity();
    emit(0);
  }
  if (want[1]) {
    RotationJacobian(parameters[1], s, rows);
    emit(1);
  }
  if (!want_shape_jacobian) return;
  const RowMajor3xN dx_df = rotation * shape_jacobian;
  const double block_weight[3] = {1.0, 1.0 - sample.knot_weight,
                                  sample.knot_weight};
  for (int block = 0; block < 3; ++block) {
    if (!want[2 + block]) continue;
    Eigen::Map<RowMajor3xN> j(rows);
    for (int function = 0; function < kNumFunctions; ++function) {
      // Block 0 (globals) supplies the functions that are not free, the
      // two knots the free ones.
      const bool free = (free_mask >> function) & 1u;
      const double weight = free != (block == 0) ? block_weight[block] : 0.0;
      j.col(function) = weight * dx_df.col(function);
    }
    emit(2 + block);
  }
}

}  // namespace

PointSample::PointSample(const Eigen::Vector3d& data, double u, double v,
                         double knot_weight)
    : data(data), angles(MakeAngles(u, v)), knot_weight(knot_weight) {}

PointSample::PointSample(const Eigen::Vector3d& data, double u, double v,
                         double knot_weight, const Eigen::Vector3d& normal)
    : data(data),
      angles(MakeAngles(u, v)),
      knot_weight(knot_weight),
      has_normal(true),
      normal(normal) {}

void EvaluatePointSample(const PointSample& sample, FunctionMask free_mask,
                         bool unit_exponents, double const* const* parameters,
                         double* residuals, double** jacobians) {
  EvaluateSample(sample, free_mask, unit_exponents, parameters,
                 RotationMatrix(parameters[1]), residuals, jacobians);
}

PointGroupResidual::PointGroupResidual(std::vector<PointSample> samples,
                                       FunctionMask free_mask,
                                       bool unit_exponents)
    : samples_(std::move(samples)),
      free_mask_(free_mask),
      unit_exponents_(unit_exponents) {
  int rows = 0;
  for (const PointSample& sample : samples_) rows += sample.num_residuals();
  set_num_residuals(rows);
  for (int size : kBlockSizes) mutable_parameter_block_sizes()->push_back(size);
}

bool PointGroupResidual::Evaluate(double const* const* parameters,
                                  double* residuals, double** jacobians) const {
  const Eigen::Matrix3d rotation = RotationMatrix(parameters[1]);
  double* rows[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  int row = 0;
  for (const PointSample& sample : samples_) {
    for (int i = 0; jacobians != nullptr && i < 5; ++i) {
      rows[i] = jacobians[i] ? jacobians[i] + row * kBlockSizes[i] : nullptr;
    }
    EvaluateSample(sample, free_mask_, unit_exponents_, parameters, rotation,
                   residuals + row, jacobians != nullptr ? rows : nullptr);
    row += sample.num_residuals();
  }
  return true;
}

}  // namespace pfdm
