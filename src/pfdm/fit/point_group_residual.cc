#include "pfdm/fit/point_group_residual.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

// Points whose nonzero entries of ds/df make a tracked group's pattern
// (PoseMomentGram).
constexpr int kPatternSamples = 32;

// Calls visit(i, s, ds) for each sample i in turn with its shape s and, if
// with_jacobian, ds = ds/df (else ds is not set), a batch at a time
// (ShapesOfBatch).  Only the first `limit` samples when limit >= 0.
template <typename Visit>
void ForEachShape(const std::vector<PointSample>& samples,
                  FunctionMask free_mask, bool unit_exponents,
                  const double* const* blocks, bool with_jacobian, Visit visit,
                  int limit = -1) {
  FunctionValues f[kShapeBatch];
  Angles<double> angles[kShapeBatch];
  double w[kShapeBatch];
  const int num_samples =
      limit < 0 ? static_cast<int>(samples.size())
                : std::min(limit, static_cast<int>(samples.size()));
  for (int first = 0; first < num_samples; first += kShapeBatch) {
    const int count = std::min(kShapeBatch, num_samples - first);
    for (int i = 0; i < count; ++i) {
      const PointSample& sample = samples[first + i];
      InterpolateFunctions(free_mask, blocks[2], blocks[3], blocks[4],
                           sample.knot_weight, f[i].data());
      angles[i] = sample.angles;
      w[i] = sample.w;
    }
    ShapesOfBatch(count, f, angles, w, unit_exponents, with_jacobian,
                  [&](int i, const Eigen::Vector3d& s,
                      const ShapeJacobian& ds) { visit(first + i, s, ds); });
  }
}

// Per-point moments summed over a group: each point fills a row of `dd`
// (the knot functions' D^T D, lower triangle packed column by column) and a
// row of `rest` (the other moments); a batch of points' rows is then
// summed weighted by (a^2, ab, b^2) and (1, a, b) respectively (a = 1 - w,
// b = w).
class MomentSums {
 public:
  // The rest's first `plain` columns are only ever read summed with weight
  // 1 and the others only with weights a and b (plain < 0: every column
  // with all three), and are summed so.
  MomentSums(int m, int num_rest, int plain = -1)
      : plain_(plain),
        m_(m),
        num_dd_(m * (m + 1) / 2),
        num_rest_(num_rest),
        dd_start_(m),
        dd_(kBatch, num_dd_),
        rest_(kBatch, num_rest),
        dd_sums_(Sums::Zero(3, num_dd_)),
        rest_sums_(Sums::Zero(3, num_rest)) {
    for (int j = 0, at = 0; j < m; at += m - j, ++j) dd_start_[j] = at - j;
  }

  // The current point's rows; dd is zeroed, rest is the caller's to fill.
  double* dd_row() {
    double* row = dd_.data() + in_batch_ * num_dd_;
    std::fill(row, row + num_dd_, 0.0);
    return row;
  }
  double* rest_row() { return rest_.data() + in_batch_ * num_rest_; }

  // Adds d d^T (d: the point's m knot columns of one row) to dd_row.
  void AddKnotProducts(const double* d, double* dd_row) const {
    for (int j = 0; j < m_; ++j) {
      const double dj = d[j];
      if (dj == 0.0) continue;
      double* pj = dd_row + dd_start_[j];
      for (int l = j; l < m_; ++l) pj[l] += dj * d[l];
    }
  }

  // Ends the current point, whose knot weight is w.
  void EndPoint(double w) {
    const double b = w, a = 1.0 - w;
    dd_weights_.row(in_batch_) << a * a, a * b, b * b;
    rest_weights_.row(in_batch_) << 1.0, a, b;
    if (++in_batch_ == kBatch) Flush();
  }

  // Plain loops, not a matrix product: for a 3-row result Eigen's product
  // spent more on packing its operands than on the multiply-adds.
  void Flush() {
    AddWeighted(dd_weights_, dd_, 0, num_dd_, 0, 3, &dd_sums_);
    if (plain_ < 0) {
      AddWeighted(rest_weights_, rest_, 0, num_rest_, 0, 3, &rest_sums_);
    } else {
      AddWeighted(rest_weights_, rest_, 0, plain_, 0, 1, &rest_sums_);
      AddWeighted(rest_weights_, rest_, plain_, num_rest_, 1, 2, &rest_sums_);
    }
    in_batch_ = 0;
  }

  // rest's sums weighted by 1 (weight 0), a (1) or b (2).
  double rest_sum(int weight, int at) const { return rest_sums_(weight, at); }

  // The knots' blocks of the Gram matrix, [(1 - w) D, w D] from column
  // first on; lower triangle only.
  void FillKnotBlocks(int first, Eigen::MatrixXd* gram) const {
    const int k = first, m = m_;
    for (int j = 0; j < m; ++j) {
      for (int i = j; i < m; ++i) {
        const int at = dd_start_[j] + i;
        (*gram)(k + i, k + j) = dd_sums_(0, at);
        (*gram)(k + m + i, k + j) = (*gram)(k + m + j, k + i) = dd_sums_(1, at);
        (*gram)(k + m + i, k + m + j) = dd_sums_(2, at);
      }
    }
  }

 private:
  static constexpr int kBatch = 32;
  using Sums = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;

  // Over the batch's points p and columns j in [begin, end): sums(k, j) +=
  // weights(p, k) rows(p, j) for the weights k in [first, first + count).
  void AddWeighted(const Eigen::Matrix<double, kBatch, 3>& weights,
                   const RowMajorMatrix& rows, int begin, int end, int first,
                   int count, Sums* sums) const {
    const int n = static_cast<int>(rows.cols());
    double* s[3];
    for (int k = 0; k < count; ++k) s[k] = sums->row(first + k).data();
    for (int p = 0; p < in_batch_; ++p) {
      const double* x = rows.data() + static_cast<size_t>(p) * n;
      double w[3];
      for (int k = 0; k < count; ++k) w[k] = weights(p, first + k);
      // One loop per count, so that each vectorizes.
      if (count == 3) {
        for (int j = begin; j < end; ++j) {
          s[0][j] += w[0] * x[j];
          s[1][j] += w[1] * x[j];
          s[2][j] += w[2] * x[j];
        }
      } else if (count == 2) {
        for (int j = begin; j < end; ++j) {
          s[0][j] += w[0] * x[j];
          s[1][j] += w[1] * x[j];
        }
      } else {
        for (int j = begin; j < end; ++j) s[0][j] += w[0] * x[j];
      }
    }
  }

  const int plain_, m_, num_dd_, num_rest_;
  std::vector<int> dd_start_;
  RowMajorMatrix dd_, rest_;
  Eigen::Matrix<double, kBatch, 3> dd_weights_, rest_weights_;
  Sums dd_sums_, rest_sums_;
  int in_batch_ = 0;
};

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
  // Each point's P in two parts: the D x D block and the rows of U and r.
  MomentSums sums(m, (k + 1) * q);
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> g(3, q);
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

    double* p_dd = sums.dd_row();
    double* p_rest = sums.rest_row();
    std::fill(p_rest, p_rest + (k + 1) * q, 0.0);
    for (int row = 0; row < num_rows; ++row) {
      const double* gr = g.data() + row * q;
      sums.AddKnotProducts(gr + k, p_dd);
      for (int c = 0; c <= k; ++c) {
        const double gc = gr[c < k ? c : r];
        if (gc == 0.0) continue;
        double* pc = p_rest + c * q;
        for (int l = 0; l < q; ++l) pc[l] += gc * gr[l];
      }
    }
    sums.EndPoint(sample.knot_weight);
  };
  ForEachShape(samples_, free_mask_, unit_exponents_, blocks, true, add_point);
  sums.Flush();

  // Into the columns [U, (1 - w) D, w D, r]; lower triangle only.  In g,
  // U is [0, k), D [k, r), r the last.
  const int n = columns_;
  enum { kOne, kA, kB };                           // The rest's weights.
  auto rest_sum = [&](int weight, int c, int l) {  // c in U or r.
    return sums.rest_sum(weight, (c < k ? c : k) * q + l);
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
  sums.FillKnotBlocks(k, &gram);
  for (int j = 0; j < m; ++j) {
    gram(n, k + j) = rest_sum(kA, r, k + j);
    gram(n, k + m + j) = rest_sum(kB, r, k + j);
  }
  gram(n, n) = rest_sum(kOne, r, r);
  return gram;
}

// MomentGram with the pose's columns folded into moments of s.  In the
// model frame a point's pose columns are R^T (the center) and
// R^T d(R(q) s)/dq = sum_a s_a V_a (the quaternion), V_a = R^T W_a and
// W_a = d(R(q) e_a)/dq, since R(q) s is linear in s; its knot columns are
// D times (1 - w) or w and its residual r = s + R^T (c - p).  So the pose's
// blocks of J^T J need only sum 1, sum s, sum s s^T, sum s r^T, sum r and,
// weighted by (1 - w) or w, sum D and sum s_a D: per point about a third of the
// products of [U D r]^T [U D r] with U's seven columns, and no rotation
// Jacobian.
Eigen::MatrixXd PointGroupResidual::PoseMomentGram(
    const double* const* blocks, const Eigen::Matrix3d& rotation) const {
  const RowLayout layout = CompactLayout(entries_);
  const int m = widths_[3];
  const int* knot_functions = layout.functions[1];
  const Eigen::Matrix3d model_from_world = rotation.transpose();
  const Eigen::Vector3d center(blocks[0]);
  // D's entries (row major, row * m + column) that the first points have
  // nonzero: ds/df is sparse, and the same way at every point of a surface
  // (the bends move z only, the twist and the offsets x and y only), so
  // its moments need only those.  A later point with another nonzero
  // entry makes the group start over with all of them.
  // D (row major) of a point: its knot functions' columns of ds/df.
  auto knot_columns = [&](const ShapeJacobian& ds, double* d) {
    for (int c = 0; c < m; ++c) {
      const bool supplied = Supplies(1, free_mask_, knot_functions[c]);
      for (int row = 0; row < 3; ++row) {
        d[row * m + c] = supplied ? ds(row, knot_functions[c]) : 0.0;
      }
    }
  };
  std::vector<int> pattern;
  {
    std::vector<bool> nonzero(3 * m, false);
    ForEachShape(
        samples_, free_mask_, unit_exponents_, blocks, true,
        [&](int, const Eigen::Vector3d&, const ShapeJacobian& ds) {
          double d[3 * kNumFunctions];
          knot_columns(ds, d);
          for (int e = 0; e < 3 * m; ++e) nonzero[e] = nonzero[e] || d[e] != 0;
        },
        kPatternSamples);
    for (int e = 0; e < 3 * m; ++e) {
      if (nonzero[e]) pattern.push_back(e);
    }
  }
  std::optional<MomentSums> sums;
  std::vector<int> at(3 * m, -1);  // Where each entry of D sits, or -1.
  int num_pattern = 0, sd_at = 0, dr_at = 0;
  // A point's moments, one row of `rest` weighted by (1, a, b) in a batch's
  // sums: [1, s, r, s s^T, s r^T, r^T r] (weight 1 is used) then
  // [D, s_a D for a = 0..2, D^T r] (weights a and b are used), D's entries
  // those of `pattern`.
  constexpr int kOne = 0, kS = 1, kR = 4, kSS = 7, kSR = 16, kRR = 25;
  constexpr int d_at = 26;
  bool outside = false;
  auto add_point = [&](int i, const Eigen::Vector3d& s,
                       const ShapeJacobian& ds) {
    const PointSample& sample = samples_[i];
    double d[3 * kNumFunctions];
    knot_columns(ds, d);
    for (int e = 0; e < 3 * m; ++e) {
      if (d[e] != 0.0 && at[e] < 0) outside = true;
    }
    double* x = sums->rest_row();
    const Eigen::Vector3d r = s + model_from_world * (center - sample.data);
    x[kOne] = 1.0;
    for (int a = 0; a < 3; ++a) {
      x[kS + a] = s[a];
      x[kR + a] = r[a];
      for (int c = 0; c < 3; ++c) {
        x[kSS + 3 * a + c] = s[a] * s[c];
        x[kSR + 3 * a + c] = s[a] * r[c];
      }
    }
    x[kRR] = r.squaredNorm();
    for (int k = 0; k < num_pattern; ++k) x[d_at + k] = d[pattern[k]];
    for (int a = 0; a < 3; ++a) {
      double* sd = x + sd_at + a * num_pattern;
      for (int k = 0; k < num_pattern; ++k) sd[k] = s[a] * d[pattern[k]];
    }
    double* dr = x + dr_at;
    for (int j = 0; j < m; ++j) {
      dr[j] = d[j] * r[0] + d[m + j] * r[1] + d[2 * m + j] * r[2];
    }
    double* p_dd = sums->dd_row();
    for (int row = 0; row < 3; ++row) sums->AddKnotProducts(d + row * m, p_dd);
    sums->EndPoint(sample.knot_weight);
  };
  for (int attempt = 0;; ++attempt) {
    std::fill(at.begin(), at.end(), -1);
    num_pattern = static_cast<int>(pattern.size());
    for (int k = 0; k < num_pattern; ++k) at[pattern[k]] = k;
    sd_at = d_at + num_pattern;
    dr_at = sd_at + 3 * num_pattern;
    sums.emplace(m, dr_at + m, d_at);
    outside = false;
    ForEachShape(samples_, free_mask_, unit_exponents_, blocks, true,
                 add_point);
    sums->Flush();
    if (!outside) break;
    CHECK_EQ(attempt, 0) << "D's entries outside all of D";
    pattern.resize(3 * m);
    for (int e = 0; e < 3 * m; ++e) pattern[e] = e;
  }

  // W_a (world, 3 x 4), V_a = R^T W_a (model frame) and U_a = V_a^T,
  // a = 0..2.  Every block is taken in the model frame, as MomentGram
  // takes them (the centre's columns R^T): the same Gram for a quaternion
  // off the unit sphere, whose R is not orthogonal (the integrator's).
  Eigen::Matrix<double, 3, 4, Eigen::RowMajor> w[3];
  Eigen::Matrix<double, 3, 4> v[3];
  Eigen::Matrix<double, 4, 3> u[3];
  for (int a = 0; a < 3; ++a) {
    RotationJacobian(blocks[1], Eigen::Vector3d::Unit(a), w[a].data());
    v[a] = model_from_world * w[a];
    u[a] = v[a].transpose();
  }
  const int n = columns_, t = 0, q = 3, k1 = 7, k2 = 7 + m;
  auto one = [&](int index) { return sums->rest_sum(0, index); };
  // sum_a s_a-weighted moments with weight row `weight` (1: a, 2: b).
  auto sd = [&](int weight, int a, int row, int l) {
    const int k = at[row * m + l];
    return k < 0 ? 0.0 : sums->rest_sum(weight, sd_at + a * num_pattern + k);
  };
  auto d_sum = [&](int weight, int row, int l) {
    const int k = at[row * m + l];
    return k < 0 ? 0.0 : sums->rest_sum(weight, d_at + k);
  };
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  // Center against center, quaternion and residual.
  const Eigen::Matrix3d center_center =
      one(kOne) * (rotation * model_from_world);
  for (int j = 0; j < 3; ++j) {
    for (int i = j; i < 3; ++i) gram(t + i, t + j) = center_center(i, j);
  }
  Eigen::Matrix<double, 3, 4> sum_v = Eigen::Matrix<double, 3, 4>::Zero();
  Eigen::Matrix4d quaternion_quaternion = Eigen::Matrix4d::Zero();
  Eigen::Vector4d quaternion_residual = Eigen::Vector4d::Zero();
  Eigen::Vector3d sum_r, sr_row;
  for (int a = 0; a < 3; ++a) {
    sum_v += one(kS + a) * v[a];
    sum_r[a] = one(kR + a);
    for (int c = 0; c < 3; ++c) {
      quaternion_quaternion += one(kSS + 3 * a + c) * (u[a] * v[c]);
      sr_row[c] = one(kSR + 3 * a + c);
    }
    quaternion_residual += u[a] * sr_row;
  }
  const Eigen::Matrix<double, 3, 4> center_quaternion = rotation * sum_v;
  const Eigen::Vector3d center_residual = rotation * sum_r;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 3; ++i) gram(q + j, t + i) = center_quaternion(i, j);
    for (int i = j; i < 4; ++i) {
      gram(q + i, q + j) = quaternion_quaternion(i, j);
    }
    gram(n, q + j) = quaternion_residual[j];
  }
  for (int i = 0; i < 3; ++i) gram(n, t + i) = center_residual[i];
  // The knots against the pose: R sum(w D) and sum_a U_a sum(w s_a D).
  for (int weight = 1; weight <= 2; ++weight) {
    const int first = weight == 1 ? k1 : k2;
    for (int l = 0; l < m; ++l) {
      Eigen::Vector3d dl, sd_l[3];
      for (int row = 0; row < 3; ++row) {
        dl[row] = d_sum(weight, row, l);
        for (int a = 0; a < 3; ++a) sd_l[a][row] = sd(weight, a, row, l);
      }
      const Eigen::Vector3d centers = rotation * dl;
      Eigen::Vector4d quaternions = Eigen::Vector4d::Zero();
      for (int a = 0; a < 3; ++a) quaternions += u[a] * sd_l[a];
      for (int i = 0; i < 3; ++i) gram(first + l, t + i) = centers[i];
      for (int j = 0; j < 4; ++j) gram(first + l, q + j) = quaternions[j];
      gram(n, first + l) = sums->rest_sum(weight, dr_at + l);
    }
  }
  sums->FillKnotBlocks(k1, &gram);
  gram(n, n) = one(kRR);
  return gram;
}

}  // namespace pfdm
