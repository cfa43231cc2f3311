#include "pfdm/fit/residuals/analytic_point_residual.h"

#include <algorithm>

#include "Eigen/Geometry"
#include "pfdm/fit/residuals/point_sample_rows.h"
#include "pfdm/model/shape_jacobian.h"

namespace pfdm {
namespace internal {

using RowMajor3xN = Eigen::Matrix<double, 3, kNumFunctions, Eigen::RowMajor>;

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

Eigen::Matrix3d RotationMatrix(const double* q) {
  const double w = q[0];
  const Eigen::Vector3d v(q[1], q[2], q[3]);
  Eigen::Matrix3d skew_v;
  skew_v << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return (1.0 - 2.0 * v.squaredNorm()) * Eigen::Matrix3d::Identity() +
         2.0 * w * skew_v + 2.0 * v * v.transpose();
}

RowLayout RowLayout::Blocks(double* const* jacobians, int row) {
  RowLayout layout;
  for (int i = 0; jacobians != nullptr && i < 5; ++i) {
    if (jacobians[i]) layout.first[i] = jacobians[i] + row * kBlockSizes[i];
  }
  return layout;
}

RowLayout CompactLayout(const std::array<const FreeEntries*, 3>& entries) {
  RowLayout layout;
  for (int b = 0; b < 3; ++b) {
    if (!entries[b]) continue;
    layout.functions[b] = entries[b]->free().data();
    layout.width[b] = entries[b]->size();
  }
  return layout;
}

void EvaluateSample(const PointSample& sample, FunctionMask free_mask,
                    bool unit_exponents, double const* const* parameters,
                    const Eigen::Matrix3d& rotation, double* residuals,
                    const RowLayout& layout) {
  double f[kNumFunctions];
  InterpolateFunctions(free_mask, parameters[2], parameters[3], parameters[4],
                       sample.knot_weight, f);
  const bool want_shape_jacobian =
      layout.first[2] || layout.first[3] || layout.first[4];
  // Without the Jacobian the templated shape is faster: its bends need
  // cosines only, where the Jacobian needs each angle's sine as well.
  ShapeJacobian shape_jacobian;
  const Eigen::Vector3d s =
      want_shape_jacobian
          ? ShapeAndJacobian(f, sample.angles, unit_exponents, &shape_jacobian,
                             sample.w)
          : ReferenceShape(f, sample.angles, unit_exponents, sample.w);
  const Eigen::Vector3d residual =
      rotation * s + Eigen::Map<const Eigen::Vector3d>(parameters[0]) -
      sample.data;
  if (sample.has_normal) {
    residuals[0] = sample.normal.dot(residual);
  } else {
    std::copy(residual.data(), residual.data() + 3, residuals);
  }

  // Writes the 3 x width rows of x, projected on the normal if there is one.
  auto emit = [&](int block, const double* rows, int width) {
    double* out = layout.first[block];
    if (sample.has_normal) {
      for (int c = 0; c < width; ++c) {
        out[c] = sample.normal[0] * rows[c] +
                 sample.normal[1] * rows[width + c] +
                 sample.normal[2] * rows[2 * width + c];
      }
      return;
    }
    for (int r = 0; r < 3; ++r) {
      std::copy(rows + r * width, rows + (r + 1) * width,
                out + r * layout.stride[block]);
    }
  };
  double rows[3 * kNumFunctions];
  if (layout.first[0]) {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rows)
        .setIdentity();
    emit(0, rows, 3);
  }
  if (layout.first[1]) {
    RotationJacobian(parameters[1], s, rows);
    emit(1, rows, 4);
  }
  if (!want_shape_jacobian) return;
  const RowMajor3xN dx_df = rotation * shape_jacobian;
  const double block_weight[3] = {1.0, 1.0 - sample.knot_weight,
                                  sample.knot_weight};
  for (int block = 0; block < 3; ++block) {
    if (!layout.first[2 + block]) continue;
    const int width = layout.width[block];
    for (int c = 0; c < width; ++c) {
      const int function = layout.functions[block][c];
      const double weight =
          Supplies(block, free_mask, function) ? block_weight[block] : 0.0;
      for (int r = 0; r < 3; ++r) {
        rows[r * width + c] = weight * dx_df(r, function);
      }
    }
    emit(2 + block, rows, width);
  }
}

}  // namespace internal

using internal::EvaluateSample;
using internal::RotationMatrix;
using internal::RowLayout;

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
                 RotationMatrix(parameters[1]), residuals,
                 RowLayout::Blocks(jacobians, 0));
}

}  // namespace pfdm
