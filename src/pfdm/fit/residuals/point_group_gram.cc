// PointGroupResidual's Gram matrices of [J r], summed from per-point
// moments without forming J (point_group_residual.h; docs/jacobians.md,
// "The Gram matrix without J").
#include <optional>
#include <vector>

#include "glog/logging.h"
#include "pfdm/fit/residuals/group_moments.h"
#include "pfdm/fit/residuals/point_group_residual.h"
#include "pfdm/fit/residuals/point_sample_rows.h"

namespace pfdm {

using internal::CompactLayout;
using internal::ForEachShape;
using internal::MomentSums;
using internal::RotationJacobian;
using internal::RowLayout;
using internal::Supplies;

namespace {

// Points whose nonzero entries of ds/df make a tracked group's pattern
// (PoseMomentGram).
constexpr int kPatternSamples = 32;

// D (row major, row * m + column) of a point: its knot functions' columns
// of ds/df.
struct KnotColumns {
  int m;
  const int* functions;
  FunctionMask free_mask;

  void operator()(const ShapeJacobian& ds, double* d) const {
    for (int c = 0; c < m; ++c) {
      const bool supplied = Supplies(1, free_mask, functions[c]);
      for (int row = 0; row < 3; ++row) {
        d[row * m + c] = supplied ? ds(row, functions[c]) : 0.0;
      }
    }
  }
};

// PoseMomentGram's sums: a point's moments, one row of `rest` weighted by
// (1, a, b) in a batch's sums: [1, s, r, s s^T, s r^T, r^T r] (weight 1 is
// used) then [D, s_a D for a = 0..2, D^T r] (weights a and b are used), D's
// entries those of `pattern`.
class PoseMoments {
 public:
  static constexpr int kOne = 0, kS = 1, kR = 4, kSS = 7, kSR = 16, kRR = 25;

  PoseMoments(int m, const std::vector<int>& pattern)
      : m_(m),
        pattern_(pattern),
        at_(3 * m, -1),
        sd_at_(kD + static_cast<int>(pattern.size())),
        dr_at_(sd_at_ + 3 * static_cast<int>(pattern.size())),
        sums_(m, dr_at_ + m, kD) {
    for (int k = 0; k < num_pattern(); ++k) at_[pattern_[k]] = k;
  }

  // Adds a point of shape s, residual r (model frame), knot columns d and
  // knot weight w.  False when d has a nonzero entry outside the pattern
  // (the sums are then of no use).
  bool Add(const Eigen::Vector3d& s, const Eigen::Vector3d& r, const double* d,
           double w) {
    bool inside = true;
    for (int e = 0; e < 3 * m_; ++e) {
      if (d[e] != 0.0 && at_[e] < 0) inside = false;
    }
    AddPoseMoments(s, r, sums_.rest_row());
    AddKnotMoments(s, r, d, sums_.rest_row());
    double* p_dd = sums_.dd_row();
    for (int row = 0; row < 3; ++row) sums_.AddKnotProducts(d + row * m_, p_dd);
    sums_.EndPoint(w);
    return inside;
  }
  void Flush() { sums_.Flush(); }

  // Sums with weight 1 of [1, s, r, s s^T, s r^T, r^T r] (index kOne ...).
  double one(int index) const { return sums_.rest_sum(0, index); }
  // Sums weighted by a (weight 1) or b (2): of D, s_a D and D^T r.
  double d_sum(int weight, int row, int l) const {
    const int k = at_[row * m_ + l];
    return k < 0 ? 0.0 : sums_.rest_sum(weight, kD + k);
  }
  double sd(int weight, int a, int row, int l) const {
    const int k = at_[row * m_ + l];
    return k < 0 ? 0.0 : sums_.rest_sum(weight, sd_at_ + a * num_pattern() + k);
  }
  double dr(int weight, int l) const {
    return sums_.rest_sum(weight, dr_at_ + l);
  }
  const MomentSums& sums() const { return sums_; }

 private:
  static constexpr int kD = 26;

  int num_pattern() const { return static_cast<int>(pattern_.size()); }

  void AddPoseMoments(const Eigen::Vector3d& s, const Eigen::Vector3d& r,
                      double* x) const {
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
  }

  void AddKnotMoments(const Eigen::Vector3d& s, const Eigen::Vector3d& r,
                      const double* d, double* x) const {
    const int num = num_pattern();
    for (int k = 0; k < num; ++k) x[kD + k] = d[pattern_[k]];
    for (int a = 0; a < 3; ++a) {
      double* sd = x + sd_at_ + a * num;
      for (int k = 0; k < num; ++k) sd[k] = s[a] * d[pattern_[k]];
    }
    double* dr = x + dr_at_;
    for (int j = 0; j < m_; ++j) {
      dr[j] = d[j] * r[0] + d[m_ + j] * r[1] + d[2 * m_ + j] * r[2];
    }
  }

  const int m_;
  const std::vector<int> pattern_;
  std::vector<int> at_;  // Where each entry of D sits, or -1.
  const int sd_at_, dr_at_;
  MomentSums sums_;
};

// D's entries (row major, row * m + column) that the first points have
// nonzero: ds/df is sparse, and the same way at every point of a surface
// (the bends move z only, the twist and the offsets x and y only), so the
// moments need only those.
std::vector<int> KnotPattern(const std::vector<PointSample>& samples,
                             FunctionMask free_mask, bool unit_exponents,
                             const double* const* blocks,
                             const KnotColumns& knot_columns) {
  const int m = knot_columns.m;
  std::vector<bool> nonzero(3 * m, false);
  ForEachShape(
      samples, free_mask, unit_exponents, blocks, true,
      [&](int, const Eigen::Vector3d&, const ShapeJacobian& ds) {
        double d[3 * kNumFunctions];
        knot_columns(ds, d);
        for (int e = 0; e < 3 * m; ++e) nonzero[e] = nonzero[e] || d[e] != 0;
      },
      kPatternSamples);
  std::vector<int> pattern;
  for (int e = 0; e < 3 * m; ++e) {
    if (nonzero[e]) pattern.push_back(e);
  }
  return pattern;
}

// The quaternion's columns in the model frame: W_a (world, 3 x 4),
// V_a = R^T W_a and U_a = V_a^T, a = 0..2.  Every block is taken in the
// model frame, as MomentGram takes them (the centre's columns R^T): the
// same Gram for a quaternion off the unit sphere, whose R is not orthogonal
// (the integrator's).
struct QuaternionColumns {
  QuaternionColumns(const double* quaternion,
                    const Eigen::Matrix3d& model_from_world) {
    for (int a = 0; a < 3; ++a) {
      Eigen::Matrix<double, 3, 4, Eigen::RowMajor> w;
      RotationJacobian(quaternion, Eigen::Vector3d::Unit(a), w.data());
      v[a] = model_from_world * w;
      u[a] = v[a].transpose();
    }
  }

  Eigen::Matrix<double, 3, 4> v[3];
  Eigen::Matrix<double, 4, 3> u[3];
};

// The pose's blocks of the Gram matrix (the centre's columns from 0, the
// quaternion's from 3, the residual's at n): the centre against itself,
// the quaternion and the residual, and the quaternion against itself and
// the residual.  Lower triangle only.
void FillPoseBlocks(const PoseMoments& moments,
                    const QuaternionColumns& columns,
                    const Eigen::Matrix3d& rotation,
                    const Eigen::Matrix3d& model_from_world, int n,
                    Eigen::MatrixXd* gram) {
  using M = PoseMoments;
  const int t = 0, q = 3;
  const Eigen::Matrix3d center_center =
      moments.one(M::kOne) * (rotation * model_from_world);
  for (int j = 0; j < 3; ++j) {
    for (int i = j; i < 3; ++i) (*gram)(t + i, t + j) = center_center(i, j);
  }
  Eigen::Matrix<double, 3, 4> sum_v = Eigen::Matrix<double, 3, 4>::Zero();
  Eigen::Matrix4d quaternion_quaternion = Eigen::Matrix4d::Zero();
  Eigen::Vector4d quaternion_residual = Eigen::Vector4d::Zero();
  Eigen::Vector3d sum_r, sr_row;
  for (int a = 0; a < 3; ++a) {
    sum_v += moments.one(M::kS + a) * columns.v[a];
    sum_r[a] = moments.one(M::kR + a);
    for (int c = 0; c < 3; ++c) {
      quaternion_quaternion +=
          moments.one(M::kSS + 3 * a + c) * (columns.u[a] * columns.v[c]);
      sr_row[c] = moments.one(M::kSR + 3 * a + c);
    }
    quaternion_residual += columns.u[a] * sr_row;
  }
  const Eigen::Matrix<double, 3, 4> center_quaternion = rotation * sum_v;
  const Eigen::Vector3d center_residual = rotation * sum_r;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 3; ++i) {
      (*gram)(q + j, t + i) = center_quaternion(i, j);
    }
    for (int i = j; i < 4; ++i) {
      (*gram)(q + i, q + j) = quaternion_quaternion(i, j);
    }
    (*gram)(n, q + j) = quaternion_residual[j];
  }
  for (int i = 0; i < 3; ++i) (*gram)(n, t + i) = center_residual[i];
}

// The knots against the pose and the residual: R sum(w D) and
// sum_a U_a sum(w s_a D), the knots' columns from 7 on, (1 - w) D's then
// w D's.
void FillKnotPoseBlocks(const PoseMoments& moments,
                        const QuaternionColumns& columns,
                        const Eigen::Matrix3d& rotation, int m, int n,
                        Eigen::MatrixXd* gram) {
  const int t = 0, q = 3, k1 = 7, k2 = 7 + m;
  for (int weight = 1; weight <= 2; ++weight) {
    const int first = weight == 1 ? k1 : k2;
    for (int l = 0; l < m; ++l) {
      Eigen::Vector3d dl, sd_l[3];
      for (int row = 0; row < 3; ++row) {
        dl[row] = moments.d_sum(weight, row, l);
        for (int a = 0; a < 3; ++a) {
          sd_l[a][row] = moments.sd(weight, a, row, l);
        }
      }
      const Eigen::Vector3d centers = rotation * dl;
      Eigen::Vector4d quaternions = Eigen::Vector4d::Zero();
      for (int a = 0; a < 3; ++a) quaternions += columns.u[a] * sd_l[a];
      for (int i = 0; i < 3; ++i) (*gram)(first + l, t + i) = centers[i];
      for (int j = 0; j < 4; ++j) (*gram)(first + l, q + j) = quaternions[j];
      (*gram)(n, first + l) = moments.dr(weight, l);
    }
  }
}

}  // namespace

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
  // n^T g into its own row first: g's row 0 from all of g would otherwise
  // be a temporary allocated per point.
  Eigen::RowVectorXd along_normal(q);
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
      along_normal.noalias() =
          (model_from_world * sample.normal).transpose() * g;
      g.row(0) = along_normal;
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
  const int m = widths_[3];
  const KnotColumns knot_columns{m, CompactLayout(entries_).functions[1],
                                 free_mask_};
  const Eigen::Matrix3d model_from_world = rotation.transpose();
  const Eigen::Vector3d center(blocks[0]);
  // Sums the moments over D's entries in `pattern`; false when a point has
  // another entry nonzero.
  std::optional<PoseMoments> moments;
  auto sum_moments = [&](const std::vector<int>& pattern) {
    moments.emplace(m, pattern);
    bool inside = true;
    ForEachShape(samples_, free_mask_, unit_exponents_, blocks, true,
                 [&](int i, const Eigen::Vector3d& s, const ShapeJacobian& ds) {
                   const PointSample& sample = samples_[i];
                   double d[3 * kNumFunctions];
                   knot_columns(ds, d);
                   const Eigen::Vector3d r =
                       s + model_from_world * (center - sample.data);
                   inside = moments->Add(s, r, d, sample.knot_weight) && inside;
                 });
    moments->Flush();
    return inside;
  };
  if (!sum_moments(KnotPattern(samples_, free_mask_, unit_exponents_, blocks,
                               knot_columns))) {
    // A later point with another nonzero entry: over all of D.
    std::vector<int> all(3 * m);
    for (int e = 0; e < 3 * m; ++e) all[e] = e;
    CHECK(sum_moments(all)) << "D's entries outside all of D";
  }
  const QuaternionColumns columns(blocks[1], model_from_world);
  const int n = columns_;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  FillPoseBlocks(*moments, columns, rotation, model_from_world, n, &gram);
  FillKnotPoseBlocks(*moments, columns, rotation, m, n, &gram);
  moments->sums().FillKnotBlocks(7, &gram);
  gram(n, n) = moments->one(PoseMoments::kRR);
  return gram;
}

}  // namespace pfdm
