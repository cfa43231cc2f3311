// Sums over a point group's samples, shared by PointGroupResidual's rows
// and its Gram matrices (point_group_gram.cc): the samples' shapes a batch
// at a time, and per-point moments summed with their knot weights.
// Internal to the library.
#ifndef PFDM_FIT_RESIDUALS_GROUP_MOMENTS_H_
#define PFDM_FIT_RESIDUALS_GROUP_MOMENTS_H_

#include <algorithm>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/residuals/analytic_point_residual.h"
#include "pfdm/fit/residuals/square_root_form.h"
#include "pfdm/model/model_point.h"
#include "pfdm/model/shape_jacobian.h"

namespace pfdm {
namespace internal {

// Calls visit(i, s, ds) for each sample i in turn with its shape s and, if
// with_jacobian, ds = ds/df (else ds is not set), a batch at a time
// (ShapesOfBatch).  Only the first `limit` samples when limit >= 0.
template <typename Visit>
inline void ForEachShape(const std::vector<PointSample>& samples,
                         FunctionMask free_mask, bool unit_exponents,
                         const double* const* blocks, bool with_jacobian,
                         Visit visit, int limit = -1) {
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

}  // namespace internal
}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_GROUP_MOMENTS_H_
