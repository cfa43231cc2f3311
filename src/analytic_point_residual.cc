#include "pfdm/analytic_point_residual.h"

#include "Eigen/Geometry"
#include "pfdm/shape_jacobian.h"

namespace pfdm {
namespace {

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

}  // namespace

AnalyticPointResidual::AnalyticPointResidual(const Eigen::Vector3d& data,
                                             double u, double v,
                                             double knot_weight,
                                             FunctionMask free_mask,
                                             bool unit_exponents)
    : data_(data),
      angles_(MakeAngles(u, v)),
      knot_weight_(knot_weight),
      free_mask_(free_mask),
      unit_exponents_(unit_exponents) {}

bool AnalyticPointResidual::Evaluate(double const* const* parameters,
                                     double* residuals,
                                     double** jacobians) const {
  const double* center = parameters[0];
  const double* quaternion = parameters[1];
  double f[kNumFunctions];
  InterpolateFunctions(free_mask_, parameters[2], parameters[3], parameters[4],
                       knot_weight_, f);
  const bool want_shape_jacobian =
      jacobians != nullptr &&
      (jacobians[2] != nullptr || jacobians[3] != nullptr ||
       jacobians[4] != nullptr);
  ShapeJacobian shape_jacobian;
  const Eigen::Vector3d s = ShapeAndJacobian(
      f, angles_, unit_exponents_, want_shape_jacobian ? &shape_jacobian : nullptr);
  const Eigen::Matrix3d rotation = RotationMatrix(quaternion);
  Eigen::Map<Eigen::Vector3d> residual(residuals);
  residual = rotation * s + Eigen::Map<const Eigen::Vector3d>(center) - data_;
  if (jacobians == nullptr) return true;

  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(jacobians[0])
        .setIdentity();
  }
  if (jacobians[1] != nullptr) RotationJacobian(quaternion, s, jacobians[1]);
  if (!want_shape_jacobian) return true;
  const RowMajor3xN dx_df = rotation * shape_jacobian;
  const double block_weight[3] = {1.0, 1.0 - knot_weight_, knot_weight_};
  for (int block = 0; block < 3; ++block) {
    double* jacobian = jacobians[2 + block];
    if (jacobian == nullptr) continue;
    Eigen::Map<RowMajor3xN> j(jacobian);
    for (int f = 0; f < kNumFunctions; ++f) {
      const bool free = (free_mask_ >> f) & 1u;
      // Block 0 (globals) supplies the non-free functions, 1 and 2 (the
      // knots) the free ones.
      const double weight = free != (block == 0) ? block_weight[block] : 0.0;
      j.col(f) = weight * dx_df.col(f);
    }
  }
  return true;
}

AnalyticSurfaceResidual::AnalyticSurfaceResidual(
    const Eigen::Vector3d& data, double u, double v, double knot_weight,
    FunctionMask free_mask, bool unit_exponents, const Eigen::Vector3d& normal)
    : point_(data, u, v, knot_weight, free_mask, unit_exponents),
      normal_(normal) {}

bool AnalyticSurfaceResidual::Evaluate(double const* const* parameters,
                                       double* residuals,
                                       double** jacobians) const {
  constexpr int kSizes[5] = {3, 4, kNumFunctions, kNumFunctions, kNumFunctions};
  double point_residual[3];
  double storage[3 * (3 + 4 + 3 * kNumFunctions)];
  double* point_jacobians[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
  if (jacobians != nullptr) {
    double* next = storage;
    for (int i = 0; i < 5; ++i) {
      if (jacobians[i] != nullptr) point_jacobians[i] = next;
      next += 3 * kSizes[i];
    }
  }
  point_.Evaluate(parameters, point_residual,
                  jacobians != nullptr ? point_jacobians : nullptr);
  residuals[0] = normal_.dot(Eigen::Map<const Eigen::Vector3d>(point_residual));
  if (jacobians == nullptr) return true;
  for (int i = 0; i < 5; ++i) {
    if (jacobians[i] == nullptr) continue;
    for (int c = 0; c < kSizes[i]; ++c) {
      jacobians[i][c] = normal_[0] * point_jacobians[i][c] +
                        normal_[1] * point_jacobians[i][kSizes[i] + c] +
                        normal_[2] * point_jacobians[i][2 * kSizes[i] + c];
    }
  }
  return true;
}

}  // namespace pfdm
