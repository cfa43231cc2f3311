#include "pfdm/fit/problem/frame_covariance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "Eigen/Cholesky"
#include "Eigen/Eigenvalues"
#include "Eigen/SparseCore"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// "tau[3] 0.71, tau[4] -0.70": the direction's largest entries.
std::string DirectionName(const std::vector<CovarianceEntry>& entries,
                          const Eigen::VectorXd& direction) {
  std::vector<int> order(direction.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(direction[a]) > std::abs(direction[b]);
  });
  std::string name;
  for (size_t i = 0; i < std::min<size_t>(3, order.size()); ++i) {
    if (std::abs(direction[order[i]]) < 0.1) break;
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%s%s %.2f", i == 0 ? "" : ", ",
                  entries[order[i]].Name().c_str(), direction[order[i]]);
    name += buffer;
  }
  return name;
}

// The top-left n x n of normal's inverse by Cholesky, when normal is
// positive definite and its condition number, estimated from below by the
// largest diagonals of A and A^-1 (within a factor n^2 of it), is under
// 1 / kMinReciprocalCondition: then the pseudo-inverse is the inverse.
// Directions the problem leaves undetermined sit at round-off (1e-16 of
// the largest), far under the cut even times n^2.
bool CholeskyInverse(const Eigen::MatrixXd& normal, int n,
                     Eigen::MatrixXd* unscaled) {
  const Eigen::LLT<Eigen::MatrixXd> llt(normal);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd inverse =
      llt.solve(Eigen::MatrixXd::Identity(normal.rows(), normal.cols()));
  const double estimate =
      normal.diagonal().maxCoeff() * inverse.diagonal().maxCoeff();
  if (!(estimate < 1.0 / kMinReciprocalCondition)) {
    return false;
  }
  *unscaled = inverse.topLeftCorner(n, n);
  return true;
}

// The pseudo-inverse's top-left n x n, dropping the eigen-directions under
// kMinReciprocalCondition times the largest; those lying mostly in the
// first n coordinates are reported.
void PseudoInverse(const Eigen::MatrixXd& normal, int n,
                   FrameCovariance* result, Eigen::MatrixXd* unscaled) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normal);
  const Eigen::VectorXd& values = eigen.eigenvalues();  // Ascending.
  const Eigen::MatrixXd& vectors = eigen.eigenvectors();
  const double cut = kMinReciprocalCondition * values[values.size() - 1];
  Eigen::VectorXd inverse_values = Eigen::VectorXd::Zero(values.size());
  for (int i = 0; i < values.size(); ++i) {
    const Eigen::VectorXd ours = vectors.col(i).head(n);
    if (values[i] >= cut) {
      inverse_values[i] = 1.0 / values[i];
    } else if (ours.norm() > 0.5) {
      ++result->rank_deficiency;
      result->deficient_directions.push_back(
          DirectionName(result->entries, ours.normalized()));
    }
  }
  const auto head = vectors.topRows(n);
  *unscaled = head * inverse_values.asDiagonal() * head.transpose();
}

}  // namespace

std::string CovarianceEntry::Name() const {
  static const char* const kAxes[] = {"x", "y", "z"};
  switch (kind) {
    case Kind::kCenter:
      return std::string("center_") + kAxes[function];
    case Kind::kRotation:
      return std::string("rotation_") + kAxes[function];
    case Kind::kGlobal:
      return FunctionName(function);
    case Kind::kKnot:
      return std::string(FunctionName(function)) + "[" + std::to_string(knot) +
             "]";
  }
  return "";
}

int FrameCovariance::IndexOf(CovarianceEntry::Kind kind, int knot,
                             int function) const {
  for (size_t i = 0; i < entries.size(); ++i) {
    const CovarianceEntry& e = entries[i];
    if (e.kind == kind && e.function == function &&
        (kind != CovarianceEntry::Kind::kKnot || e.knot == knot)) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int FrameCovariance::FunctionIndex(const ModelConfig& config, int f,
                                   int k) const {
  return config.modes[f] == FunctionMode::kFree
             ? IndexOf(CovarianceEntry::Kind::kKnot, k, f)
             : IndexOf(CovarianceEntry::Kind::kGlobal, -1, f);
}

double FrameCovariance::KnotSd(const ModelConfig& config, int f, int k) const {
  if (!computed) return 0.0;
  const int i = FunctionIndex(config, f, k);
  return i < 0 ? 0.0 : std::sqrt(std::max(0.0, covariance(i, i)));
}

// The columns: `blocks` first, then every other free block of the problem
// (the axis gauge chain's partial sums: holding them would pin each knot's
// offset instead of their sum), all in tangent coordinates.
std::vector<double*> ColumnOrder(ceres::Problem* problem,
                                 const std::vector<CovarianceBlock>& blocks) {
  std::vector<double*> order;
  for (const CovarianceBlock& block : blocks) {
    order.push_back(const_cast<double*>(block.parameters));
  }
  std::vector<double*> all;
  problem->GetParameterBlocks(&all);
  for (double* parameters : all) {
    if (problem->IsParameterBlockConstant(parameters) ||
        std::find(order.begin(), order.end(), parameters) != order.end()) {
      continue;
    }
    order.push_back(parameters);
  }
  return order;
}

FrameCovariance BlockCovariance(ceres::Problem* problem,
                                const std::vector<CovarianceBlock>& blocks,
                                double sigma_mm, double degrees_of_freedom) {
  const auto start = Clock::now();
  FrameCovariance result;
  result.sigma_mm = sigma_mm;
  result.degrees_of_freedom = degrees_of_freedom;
  for (const CovarianceBlock& block : blocks) {
    result.entries.insert(result.entries.end(), block.entries.begin(),
                          block.entries.end());
  }
  const int n = static_cast<int>(result.entries.size());
  // What ceres::Covariance's DENSE_SVD with null_space_rank -1 gives (the
  // test checks it), from J'J's eigen-decomposition instead of the SVD of
  // the dense J: that SVD of a frame's thousands of rows took 0.4 s of a
  // 2,000-tag tracked frame whose whole fit took 0.14 s.  J'J squares the
  // condition number, which the cut at kMinReciprocalCondition (singular
  // values 1e-5 of the largest) stays far above double's round-off.
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = ColumnOrder(problem, blocks);
  ceres::CRSMatrix jacobian;
  if (n == 0 ||
      !problem->Evaluate(options, nullptr, nullptr, nullptr, &jacobian)) {
    result.seconds = SecondsSince(start);
    return result;
  }
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> j(
      jacobian.num_rows, jacobian.num_cols,
      static_cast<int>(jacobian.values.size()), jacobian.rows.data(),
      jacobian.cols.data(), jacobian.values.data());
  const Eigen::MatrixXd normal =
      Eigen::SparseMatrix<double>(j.transpose() * j).toDense();
  Eigen::MatrixXd unscaled;
  if (!CholeskyInverse(normal, n, &unscaled)) {
    PseudoInverse(normal, n, &result, &unscaled);
  }
  result.covariance = sigma_mm * sigma_mm * unscaled;
  result.computed = true;
  result.seconds = SecondsSince(start);
  return result;
}

void DataSigma(const Model& model, const std::vector<Eigen::Vector3d>& points,
               const std::vector<MaterialPoint>& material,
               const std::vector<Eigen::Vector3d>& normals,
               const std::string& loss, double loss_scale_mm,
               int num_parameters, double* sigma_mm,
               double* degrees_of_freedom) {
  const std::vector<Eigen::Vector3d> at = WorldPoints(model, material);
  std::vector<Eigen::Vector3d> residuals(points.size());
  std::vector<int> dimensions(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) {
    residuals[i] = at[i] - points[i];
    if (normals[i] != Eigen::Vector3d::Zero()) {
      residuals[i] = normals[i] * normals[i].dot(residuals[i]);
      dimensions[i] = 1;
    }
  }
  const std::vector<double> weights =
      LossWeights(loss, loss_scale_mm, residuals);
  double sum = 0.0, count = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    sum += weights[i] * residuals[i].squaredNorm();
    count += weights[i] * dimensions[i];
  }
  *degrees_of_freedom = std::max(1.0, count - num_parameters);
  *sigma_mm = std::sqrt(sum / *degrees_of_freedom);
}

}  // namespace pfdm
