#include "pfdm/fit/residuals/point_group_residual.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "glog/logging.h"
#include "pfdm/fit/residuals/group_moments.h"
#include "pfdm/fit/residuals/point_sample_rows.h"
#include "pfdm/model/shape_jacobian.h"
#include "pfdm/util/batch_trig.h"

namespace pfdm {

using internal::CompactLayout;
using internal::EvaluateSample;
using internal::ForEachShape;
using internal::kAllFunctions;
using internal::kBlockSizes;
using internal::RotationJacobian;
using internal::RotationMatrix;
using internal::RowLayout;
using internal::Supplies;

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
  const auto functions = [this](int knot) {
    return entries_[knot]
               ? entries_[knot]->free()
               : std::vector<int>(kAllFunctions, kAllFunctions + kNumFunctions);
  };
  knots_alike_ = varied_[3] && varied_[4] && functions(1) == functions(2);
  pose_moments_ =
      knots_alike_ && varied_[0] && varied_[1] && !varied_[2] &&
      std::none_of(samples_.begin(), samples_.end(),
                   [](const PointSample& sample) { return sample.has_normal; });
  set_num_residuals(compressed_ ? columns_ + 1 : rows_);
}

bool PointGroupResidual::Evaluate(double const* const* parameters,
                                  double* residuals, double** jacobians) const {
  const bool with_jacobians = jacobians != nullptr;
  if (!compressed_) {
    FunctionValues whole[3];
    const double* blocks[5];
    WholeBlocks(parameters, whole, blocks);
    const Eigen::Matrix3d rotation = RotationMatrix(parameters[1]);
    RowLayout layout = CompactLayout(entries_);
    for (int b = 0; b < 5; ++b) layout.stride[b] = widths_[b];
    int row = 0;
    for (const PointSample& sample : samples_) {
      for (int b = 0; with_jacobians && b < 5; ++b) {
        layout.first[b] =
            jacobians[b] ? jacobians[b] + row * widths_[b] : nullptr;
      }
      EvaluateSample(sample, free_mask_, unit_exponents_, blocks, rotation,
                     residuals + row, layout);
      row += sample.num_residuals();
    }
    return true;
  }
  if ((precomputed_.with_jacobians || !with_jacobians) &&
      IsAt(precomputed_, parameters)) {
    Write(precomputed_, residuals, jacobians);
  } else {
    Write(Compute(parameters, with_jacobians), residuals, jacobians);
  }
  return true;
}

void PointGroupResidual::WholeBlocks(double const* const* parameters,
                                     FunctionValues whole[3],
                                     const double* blocks[5]) const {
  std::copy(parameters, parameters + 5, blocks);
  for (int b = 0; b < 3; ++b) {
    if (!entries_[b]) continue;
    entries_[b]->Expand(parameters[2 + b], whole[b].data());
    blocks[2 + b] = whole[b].data();
  }
}

double PointGroupResidual::Precompute(double const* const* parameters,
                                      bool with_jacobians) const {
  if (!compressed_) return 0.0;
  precomputed_ = Compute(parameters, with_jacobians);
  for (int b = 0; b < 5; ++b) {
    precomputed_.at.insert(precomputed_.at.end(), parameters[b],
                           parameters[b] + widths_[b]);
  }
  return precomputed_.norm * precomputed_.norm;
}

bool PointGroupResidual::IsAt(const Result& result,
                              double const* const* parameters) const {
  if (result.at.empty()) return false;
  const double* at = result.at.data();
  for (int b = 0; b < 5; ++b) {
    if (!std::equal(parameters[b], parameters[b] + widths_[b], at)) {
      return false;
    }
    at += widths_[b];
  }
  return true;
}

PointGroupResidual::Result PointGroupResidual::Compute(
    double const* const* parameters, bool with_jacobians) const {
  Result result;
  result.with_jacobians = with_jacobians;
  FunctionValues whole[3];
  const double* blocks[5];
  WholeBlocks(parameters, whole, blocks);
  const Eigen::Matrix3d rotation = RotationMatrix(parameters[1]);
  if (!with_jacobians) {
    result.norm = ResidualNorm(blocks, rotation);
    return result;
  }
  auto stacked = [&] { return StackedRows(blocks, rotation); };
  result.form =
      pose_moments_
          ? SquareRootFormFromGram(PoseMomentGram(blocks, rotation), stacked)
      : knots_alike_
          ? SquareRootFormFromGram(MomentGram(blocks, rotation), stacked)
          : ToSquareRootForm(stacked());
  result.norm = std::sqrt(result.form.z.squaredNorm() +
                          result.form.rho * result.form.rho);
  return result;
}

void PointGroupResidual::Write(const Result& result, double* residuals,
                               double** jacobians) const {
  const int n = columns_;
  std::fill(residuals, residuals + n + 1, 0.0);
  if (jacobians == nullptr) {
    residuals[0] = result.norm;
    return;
  }
  const SquareRootForm& form = result.form;
  std::copy(form.z.data(), form.z.data() + n, residuals);
  residuals[n] = form.rho;
  for (int b = 0; b < 5; ++b) {
    if (!jacobians[b]) continue;
    CHECK(varied_[b]) << "Jacobian asked for a block the group holds fixed";
    Eigen::Map<RowMajorMatrix> jacobian(jacobians[b], n + 1, widths_[b]);
    jacobian.topRows(n) = form.r.middleCols(offsets_[b], widths_[b]);
    jacobian.row(n).setZero();
  }
}

// The norm of the stacked residual rows.
double PointGroupResidual::ResidualNorm(const double* const* blocks,
                                        const Eigen::Matrix3d& rotation) const {
  const Eigen::Vector3d center(blocks[0]);
  double squared_norm = 0.0;
  ForEachShape(samples_, free_mask_, unit_exponents_, blocks, false,
               [&](int i, const Eigen::Vector3d& s, const ShapeJacobian&) {
                 const PointSample& sample = samples_[i];
                 const Eigen::Vector3d r = rotation * s + center - sample.data;
                 squared_norm += sample.has_normal
                                     ? std::pow(sample.normal.dot(r), 2)
                                     : r.squaredNorm();
               });
  return std::sqrt(squared_norm);
}

// [J r] of the varied blocks, one row per residual row.
RowMajorMatrix PointGroupResidual::StackedRows(
    const double* const* blocks, const Eigen::Matrix3d& rotation) const {
  RowLayout layout = CompactLayout(entries_);
  RowMajorMatrix stacked(rows_, columns_ + 1);
  const int width = static_cast<int>(stacked.cols());
  for (int b = 0; b < 5; ++b) layout.stride[b] = width;
  int row = 0;
  double sample_residuals[3];
  for (const PointSample& sample : samples_) {
    for (int b = 0; b < 5; ++b) {
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
  return stacked;
}
}  // namespace pfdm
