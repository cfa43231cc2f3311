#include "pfdm/fit/point_group_residual.h"

#include <algorithm>
#include <cmath>

#include "glog/logging.h"
#include "pfdm/fit/point_sample_rows.h"
#include "pfdm/model/shape_jacobian.h"
#include "pfdm/util/batch_trig.h"

namespace pfdm {

using internal::CompactLayout;
using internal::EvaluateSample;
using internal::kAllFunctions;
using internal::kBlockSizes;
using internal::RotationJacobian;
using internal::RotationMatrix;
using internal::RowLayout;
using internal::Supplies;

namespace {

// Calls visit(i, s, ds) for each sample i in turn with its shape s and, if
// with_jacobian, ds = ds/df (else ds is not set), taking the samples'
// sines and cosines a batch at a time.
template <typename Visit>
void ForEachShape(const std::vector<PointSample>& samples,
                  FunctionMask free_mask, bool unit_exponents,
                  const double* const* blocks, bool with_jacobian,
                  Visit visit) {
  constexpr int kBatch = 32;
  double f[kBatch][kNumFunctions];
  ShapePrelude preludes[kBatch];
  double angles[kBatch * kNumShapeAngles];
  double sines[kBatch * kNumShapeAngles], cosines[kBatch * kNumShapeAngles];
  ShapeJacobian ds;
  const int num_samples = static_cast<int>(samples.size());
  for (int first = 0; first < num_samples; first += kBatch) {
    const int count = std::min(kBatch, num_samples - first);
    for (int i = 0; i < count; ++i) {
      const PointSample& sample = samples[first + i];
      InterpolateFunctions(free_mask, blocks[2], blocks[3], blocks[4],
                           sample.knot_weight, f[i]);
      preludes[i] = PrepareShape(f[i], sample.angles, unit_exponents, sample.w);
      std::copy(preludes[i].angles, preludes[i].angles + kNumShapeAngles,
                angles + i * kNumShapeAngles);
    }
    SinCosMany(angles, count * kNumShapeAngles, sines, cosines);
    for (int i = 0; i < count; ++i) {
      const int at = i * kNumShapeAngles;
      const Eigen::Vector3d s =
          ShapeAndJacobian(f[i], preludes[i], sines + at, cosines + at,
                           with_jacobian ? &ds : nullptr);
      visit(first + i, s, ds);
    }
  }
}

}  // namespace

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
    return entries_[knot] ? entries_[knot]->free()
                          : std::vector<int>(kAllFunctions, kAllFunctions + kNumFunctions);
  };
  knots_alike_ = varied_[3] && varied_[4] && functions(1) == functions(2);
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
  if (!compressed_) {
    RowLayout layout = CompactLayout(entries_);
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

  const int n = columns_;
  std::fill(residuals, residuals + n + 1, 0.0);
  auto stacked = [&] { return StackedRows(blocks, rotation); };
  if (jacobians == nullptr) {
    residuals[0] = ResidualNorm(blocks, rotation);
    return true;
  }
  const SquareRootForm form =
      knots_alike_
          ? SquareRootFormFromGram(MomentGram(blocks, rotation), stacked)
          : ToSquareRootForm(stacked());
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

// The Gram matrix of [J r] without forming J.  Two facts make it cheap.
// R is orthogonal, so a point's rows may be taken in the model frame, as
// R^T [J_i r_i] = [R^T, R^T dRs/dq, ds/df, R^T r_i] (n^T becomes (R^T n)^T),
// where ds/df is sparse: the bends move z only, the twist x and y only.
// And the two knots' columns are (1 - w) D and w D for the same D, so with
// the point's g = [U D r] (U: the pose and globals columns) and
// P = g^T g, J^T J takes P's blocks weighted by 1, (1 - w), w, (1 - w)^2,
// w (1 - w) or w^2: one small P per point instead of the twice wider rank
// update of [U (1 - w)D w D r].
Eigen::MatrixXd PointGroupResidual::MomentGram(
    const double* const* blocks, const Eigen::Matrix3d& rotation) const {
  const RowLayout layout = CompactLayout(entries_);
  const int k = offsets_[3], m = widths_[3], q = k + m + 1, r = q - 1;
  const Eigen::Matrix3d model_from_world = rotation.transpose();
  const Eigen::Vector3d center(blocks[0]);
  const int* knot_functions = layout.functions[1];
  // Each point's P in two parts, each a row of a matrix: the D x D block
  // (lower triangle, packed column by column) and the rows of U and r; a
  // batch of points' sums, weighted by (a^2, ab, b^2) and (1, a, b)
  // respectively (a = 1 - w, b = w), is then one matrix product each.
  const int num_dd = m * (m + 1) / 2, num_rest = (k + 1) * q;
  std::vector<int> dd_start(m);
  for (int j = 0, at = 0; j < m; at += m - j, ++j) dd_start[j] = at - j;
  constexpr int kBatch = 32;
  RowMajorMatrix dd(kBatch, num_dd), rest(kBatch, num_rest);
  Eigen::Matrix<double, kBatch, 3> dd_weights, rest_weights;
  Eigen::Matrix<double, 3, Eigen::Dynamic> dd_sums =
      Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, num_dd);
  Eigen::Matrix<double, 3, Eigen::Dynamic> rest_sums =
      Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, num_rest);
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> g(3, q);
  int in_batch = 0;
  auto flush = [&] {
    dd_sums.noalias() +=
        dd_weights.topRows(in_batch).transpose() * dd.topRows(in_batch);
    rest_sums.noalias() +=
        rest_weights.topRows(in_batch).transpose() * rest.topRows(in_batch);
    in_batch = 0;
  };
  auto add_point = [&](int i, const Eigen::Vector3d& s,
                       const ShapeJacobian& ds) {
    const PointSample& sample = samples_[i];
    int column = 0;
    if (varied_[0]) {
      g.middleCols<3>(column) = model_from_world;
      column += 3;
    }
    if (varied_[1]) {
      double world[12];
      RotationJacobian(blocks[1], s, world);
      g.middleCols<4>(column) =
          model_from_world *
          Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>>(world);
      column += 4;
    }
    auto add_columns = [&](int block, int width, const int* functions) {
      for (int c = 0; c < width; ++c, ++column) {
        if (Supplies(block, free_mask_, functions[c])) {
          g.col(column) = ds.col(functions[c]);
        } else {
          g.col(column).setZero();
        }
      }
    };
    if (varied_[2]) add_columns(0, widths_[2], layout.functions[0]);
    add_columns(1, m, knot_functions);
    g.col(r) = s + model_from_world * (center - sample.data);
    int num_rows = 3;
    if (sample.has_normal) {
      g.row(0) = (model_from_world * sample.normal).transpose() * g;
      num_rows = 1;
    }

    double* p_dd = dd.data() + in_batch * num_dd;
    double* p_rest = rest.data() + in_batch * num_rest;
    std::fill(p_dd, p_dd + num_dd, 0.0);
    std::fill(p_rest, p_rest + num_rest, 0.0);
    for (int row = 0; row < num_rows; ++row) {
      const double* gr = g.data() + row * q;
      for (int j = 0; j < m; ++j) {
        const double gj = gr[k + j];
        if (gj == 0.0) continue;
        double* pj = p_dd + dd_start[j];
        for (int l = j; l < m; ++l) pj[l] += gj * gr[k + l];
      }
      for (int c = 0; c <= k; ++c) {
        const double gc = gr[c < k ? c : r];
        if (gc == 0.0) continue;
        double* pc = p_rest + c * q;
        for (int l = 0; l < q; ++l) pc[l] += gc * gr[l];
      }
    }
    const double b = sample.knot_weight, a = 1.0 - b;
    dd_weights.row(in_batch) << a * a, a * b, b * b;
    rest_weights.row(in_batch) << 1.0, a, b;
    if (++in_batch == kBatch) flush();
  };
  ForEachShape(samples_, free_mask_, unit_exponents_, blocks, true, add_point);
  if (in_batch > 0) flush();

  // Into the columns [U, (1 - w) D, w D, r]; lower triangle only.  In g,
  // U is [0, k), D [k, r), r the last.
  const int n = columns_;
  enum { kOne, kA, kB };  // rest_sums' rows; dd_sums' are aa, ab, bb.
  auto rest_sum = [&](int weight, int c, int l) {  // c in U or r.
    return rest_sums(weight, (c < k ? c : k) * q + l);
  };
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int j = 0; j < k; ++j) {
    for (int i = j; i < k; ++i) gram(i, j) = rest_sum(kOne, j, i);
    for (int i = k; i < r; ++i) {
      gram(i, j) = rest_sum(kA, j, i);
      gram(i + m, j) = rest_sum(kB, j, i);
    }
    gram(n, j) = rest_sum(kOne, r, j);
  }
  for (int j = 0; j < m; ++j) {
    for (int i = j; i < m; ++i) {
      const int at = dd_start[j] + i;
      gram(k + i, k + j) = dd_sums(0, at);
      gram(k + m + i, k + j) = gram(k + m + j, k + i) = dd_sums(1, at);
      gram(k + m + i, k + m + j) = dd_sums(2, at);
    }
    gram(n, k + j) = rest_sum(kA, r, k + j);
    gram(n, k + m + j) = rest_sum(kB, r, k + j);
  }
  gram(n, n) = rest_sum(kOne, r, r);
  return gram;
}

}  // namespace pfdm
