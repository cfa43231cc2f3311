#include "pfdm/analytic_point_residual.h"

#include <algorithm>

#include "Eigen/Geometry"
#include "glog/logging.h"
#include "pfdm/shape_jacobian.h"
#include "pfdm/square_root_form.h"

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

constexpr int kAllFunctions[kNumFunctions] = {0, 1, 2, 3,  4,  5,  6,
                                              7, 8, 9, 10, 11, 12, 13};

// Where EvaluateSample writes a sample's Jacobian rows: per block the first
// row (null: not wanted) and the distance between rows; for the globals and
// the two knots, which functions their columns are.
struct RowLayout {
  double* first[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  int stride[5] = {3, 4, kNumFunctions, kNumFunctions, kNumFunctions};
  const int* functions[3] = {kAllFunctions, kAllFunctions, kAllFunctions};
  int width[3] = {kNumFunctions, kNumFunctions, kNumFunctions};

  // Each block's rows where Ceres wants them (row major, block wide).
  static RowLayout Blocks(double* const* jacobians, int row) {
    RowLayout layout;
    for (int i = 0; jacobians != nullptr && i < 5; ++i) {
      if (jacobians[i]) layout.first[i] = jacobians[i] + row * kBlockSizes[i];
    }
    return layout;
  }
};

// Writes one sample's residual rows and the Jacobian rows `layout` asks
// for.  parameters are the whole blocks.
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
          ? ShapeAndJacobian(f, sample.angles, unit_exponents, &shape_jacobian)
          : ReferenceShape(f, sample.angles, unit_exponents);
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
      // The globals supply the functions that are not free, the two knots
      // the free ones.
      const int function = layout.functions[block][c];
      const bool free = (free_mask >> function) & 1u;
      const double weight = free != (block == 0) ? block_weight[block] : 0.0;
      for (int r = 0; r < 3; ++r) {
        rows[r * width + c] = weight * dx_df(r, function);
      }
    }
    emit(2 + block, rows, width);
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
                 RotationMatrix(parameters[1]), residuals,
                 RowLayout::Blocks(jacobians, 0));
}

PointGroupResidual::PointGroupResidual(
    std::vector<PointSample> samples, FunctionMask free_mask,
    bool unit_exponents, std::array<const FreeEntries*, 3> entries,
    std::array<bool, 5> varied)
    : samples_(std::move(samples)),
      free_mask_(free_mask),
      unit_exponents_(unit_exponents),
      entries_(entries),
      varied_(varied) {
  for (const PointSample& sample : samples_) rows_ += sample.num_residuals();
  for (int b = 0; b < 5; ++b) {
    widths_[b] =
        b >= 2 && entries_[b - 2] ? entries_[b - 2]->size() : kBlockSizes[b];
    mutable_parameter_block_sizes()->push_back(widths_[b]);
    offsets_[b] = columns_;
    if (varied_[b]) columns_ += widths_[b];
  }
  compressed_ = columns_ > 0 && rows_ > columns_ + 1;
  set_num_residuals(compressed_ ? columns_ + 1 : rows_);
}

bool PointGroupResidual::Evaluate(double const* const* parameters,
                                  double* residuals, double** jacobians) const {
  FunctionValues whole[3];
  const double* blocks[5] = {parameters[0], parameters[1], parameters[2],
                             parameters[3], parameters[4]};
  for (int b = 0; b < 3; ++b) {
    if (!entries_[b]) continue;
    entries_[b]->Expand(parameters[2 + b], whole[b].data());
    blocks[2 + b] = whole[b].data();
  }
  const Eigen::Matrix3d rotation = RotationMatrix(parameters[1]);
  RowLayout layout;
  for (int b = 0; b < 3; ++b) {
    if (!entries_[b]) continue;
    layout.functions[b] = entries_[b]->free().data();
    layout.width[b] = entries_[b]->size();
  }

  if (!compressed_) {
    for (int b = 0; b < 5; ++b) layout.stride[b] = widths_[b];
    int row = 0;
    for (const PointSample& sample : samples_) {
      for (int b = 0; jacobians != nullptr && b < 5; ++b) {
        layout.first[b] =
            jacobians[b] ? jacobians[b] + row * widths_[b] : nullptr;
      }
      EvaluateSample(sample, free_mask_, unit_exponents_, blocks, rotation,
                     residuals + row, layout);
      row += sample.num_residuals();
    }
    return true;
  }

  // Square-root form: the stacked rows [J r] first, in one dense matrix.
  const int n = columns_;
  RowMajorMatrix stacked(rows_, jacobians != nullptr ? n + 1 : 1);
  const int width = static_cast<int>(stacked.cols());
  for (int b = 0; b < 5; ++b) layout.stride[b] = width;
  int row = 0;
  double sample_residuals[3];
  for (const PointSample& sample : samples_) {
    for (int b = 0; jacobians != nullptr && b < 5; ++b) {
      layout.first[b] =
          varied_[b] ? stacked.data() + row * width + offsets_[b] : nullptr;
    }
    EvaluateSample(sample, free_mask_, unit_exponents_, blocks, rotation,
                   sample_residuals, layout);
    for (int i = 0; i < sample.num_residuals(); ++i) {
      stacked(row + i, width - 1) = sample_residuals[i];
    }
    row += sample.num_residuals();
  }
  std::fill(residuals, residuals + n + 1, 0.0);
  if (jacobians == nullptr) {
    residuals[0] = stacked.norm();
    return true;
  }
  const SquareRootForm form = ToSquareRootForm(stacked);
  std::copy(form.z.data(), form.z.data() + n, residuals);
  residuals[n] = form.rho;
  for (int b = 0; b < 5; ++b) {
    if (!jacobians[b]) continue;
    CHECK(varied_[b]) << "Jacobian asked for a block the group holds fixed";
    Eigen::Map<RowMajorMatrix> jacobian(jacobians[b], n + 1, widths_[b]);
    jacobian.topRows(n) = form.r.middleCols(offsets_[b], widths_[b]);
    jacobian.row(n).setZero();
  }
  return true;
}

}  // namespace pfdm
