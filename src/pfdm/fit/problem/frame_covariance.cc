#include "pfdm/fit/problem/frame_covariance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "Eigen/Cholesky"
#include "Eigen/Eigenvalues"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/solvers/normal_matrix.h"
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

// J'J scaled to a unit diagonal, D^-1/2 J'J D^-1/2 (D its diagonal), and
// D^-1/2 in *scale.  The gauge residuals' stiff weights (10 sqrt(N) on
// each, kGaugeWeight) put a few diagonal entries 1e4-1e6 times above the
// data's, so J'J's condition number measured the gauge's weight, not what
// the data leave undetermined: it failed the Cholesky's test below on
// every tracked frame and sent it to the eigen-decomposition, 15 of a 2,000
// tag frame's 24 ms.  Scaled, each coordinate is measured against its own
// curvature.  A coordinate nothing sees (diagonal 0) keeps scale 0: its
// variance comes out 0 and its direction is reported by the caller's
// pseudo-inverse.
Eigen::MatrixXd UnitDiagonal(const Eigen::MatrixXd& normal,
                             Eigen::VectorXd* scale) {
  const Eigen::VectorXd diagonal = normal.diagonal();
  *scale = Eigen::VectorXd::Zero(diagonal.size());
  for (int i = 0; i < diagonal.size(); ++i) {
    if (diagonal[i] > 0.0) (*scale)[i] = 1.0 / std::sqrt(diagonal[i]);
  }
  Eigen::MatrixXd scaled = scale->asDiagonal() * normal * scale->asDiagonal();
  for (int i = 0; i < diagonal.size(); ++i) {
    if (diagonal[i] <= 0.0) scaled(i, i) = 0.0;
  }
  return scaled;
}

// A's inverse by Cholesky, A = scaled with its unit
// diagonal, when A is positive definite and its condition number,
// estimated from below by the largest diagonal of A^-1 (A's are 1; within
// a factor n^2 of it), is under 1 / kMinReciprocalCondition: then the
// pseudo-inverse is the inverse.  Directions the problem leaves
// undetermined sit at round-off (1e-16 of the largest), far under the cut
// even times n^2.
bool CholeskyInverse(const Eigen::MatrixXd& scaled, Eigen::MatrixXd* unscaled) {
  const Eigen::LLT<Eigen::MatrixXd> llt(scaled);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd inverse =
      llt.solve(Eigen::MatrixXd::Identity(scaled.rows(), scaled.cols()));
  if (!(inverse.diagonal().maxCoeff() < 1.0 / kMinReciprocalCondition)) {
    return false;
  }
  *unscaled = inverse;
  return true;
}

// The pseudo-inverse of the unit-diagonal A, dropping the
// eigen-directions under kMinReciprocalCondition times the largest; those
// lying mostly in the first n coordinates are reported.
void PseudoInverse(const Eigen::MatrixXd& scaled, int n,
                   FrameCovariance* result, Eigen::MatrixXd* unscaled) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled);
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
  *unscaled = vectors * inverse_values.asDiagonal() * vectors.transpose();
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

double FrameCovariance::LengthNoiseMean() const {
  if (length_noise.empty()) return 0.0;
  return Eigen::Map<const Eigen::VectorXd>(length_noise.data(),
                                           length_noise.size())
      .mean();
}

double FrameCovariance::LengthNoiseVariance() const {
  if (length_noise.size() < 2) return apex_length_variance;
  const Eigen::Map<const Eigen::VectorXd> f(length_noise.data(),
                                            length_noise.size());
  return (f.array() - f.mean()).square().sum() /
             (static_cast<double>(f.size()) - 1) +
         apex_length_variance;
}

double ApexAxialVariance(const FrameCovariance& covariance,
                         const Model& model) {
  if (!covariance.computed) return 0.0;
  const Eigen::Vector3d axis = model.Rotation().col(2);
  double variance = 0.0;
  for (int i = 0; i < 3; ++i) {
    const int a = covariance.IndexOf(CovarianceEntry::Kind::kCenter, -1, i);
    for (int j = 0; j < 3; ++j) {
      const int b = covariance.IndexOf(CovarianceEntry::Kind::kCenter, -1, j);
      if (a < 0 || b < 0) continue;
      variance += axis[i] * axis[j] * covariance.covariance(a, b);
    }
  }
  return std::max(0.0, variance);
}

double FrameCovariance::KnotSd(const ModelConfig& config, int f, int k) const {
  if (!computed) return 0.0;
  const int i = FunctionIndex(config, f, k);
  return i < 0 ? 0.0 : std::sqrt(std::max(0.0, covariance(i, i)));
}

namespace {

// J'J over `columns`, and J_d'J_d of its first data_rows rows, the data's
// (the problem's residual blocks come in the order they were added, the
// data's first: frame_problem.cc).
bool NormalMatrices(ceres::Problem* problem,
                    const std::vector<double*>& columns, int data_rows,
                    Eigen::MatrixXd* normal, Eigen::MatrixXd* data_normal) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = columns;
  ceres::CRSMatrix jacobian;
  if (!problem->Evaluate(options, nullptr, nullptr, nullptr, &jacobian)) {
    return false;
  }
  if (normal != nullptr) *normal = GaussNewtonMatrix(jacobian);
  *data_normal = GaussNewtonMatrix(jacobian, data_rows);
  return true;
}

int CountDataRows(ceres::Problem* problem,
                  const std::vector<ceres::ResidualBlockId>& data) {
  int rows = 0;
  for (ceres::ResidualBlockId id : data) {
    if (id == nullptr) continue;  // A constant, left out (frame_blocks.h).
    rows += problem->GetCostFunctionForResidualBlock(id)->num_residuals();
  }
  return rows;
}

}  // namespace

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
                                double sigma_mm, double degrees_of_freedom,
                                const std::vector<ceres::ResidualBlockId>& data,
                                NormalParts* parts) {
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
  const std::vector<double*> columns = ColumnOrder(problem, blocks);
  Eigen::MatrixXd normal, data_normal;
  if (n == 0 || !NormalMatrices(problem, columns, CountDataRows(problem, data),
                                &normal, &data_normal)) {
    result.seconds = SecondsSince(start);
    return result;
  }
  Eigen::VectorXd scale;
  const Eigen::MatrixXd scaled = UnitDiagonal(normal, &scale);
  Eigen::MatrixXd inverse;  // Of `scaled`.
  if (!CholeskyInverse(scaled, &inverse)) {
    PseudoInverse(scaled, n, &result, &inverse);
  }
  // tr((J'J)^+ J_d'J_d), in the scaled coordinates as tr(A^+ D J_d'J_d D).
  result.effective_parameters =
      inverse
          .cwiseProduct(scale.asDiagonal() * data_normal * scale.asDiagonal())
          .sum();
  const auto head_scale = scale.head(n).asDiagonal();
  result.covariance = sigma_mm * sigma_mm *
                      (head_scale * inverse.topLeftCorner(n, n) * head_scale);
  if (parts != nullptr) {
    parts->pseudo_inverse = scale.asDiagonal() * inverse * scale.asDiagonal();
    parts->data_normal = std::move(data_normal);
  }
  result.computed = true;
  result.seconds = SecondsSince(start);
  return result;
}

Eigen::MatrixXd DataNormalMatrix(
    ceres::Problem* problem, const std::vector<CovarianceBlock>& blocks,
    const std::vector<ceres::ResidualBlockId>& data) {
  Eigen::MatrixXd data_normal;
  if (!NormalMatrices(problem, ColumnOrder(problem, blocks),
                      CountDataRows(problem, data), nullptr, &data_normal)) {
    return {};
  }
  return data_normal;
}

void DataSigma(const Model& model, const std::vector<Eigen::Vector3d>& points,
               const std::vector<MaterialPoint>& material,
               const std::vector<Eigen::Vector3d>& normals,
               const std::string& loss, double loss_scale_mm,
               double num_parameters, double* sigma_mm,
               double* degrees_of_freedom) {
  std::vector<Eigen::Vector3d> residuals = Residuals(model, points, material);
  std::vector<int> dimensions(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) {
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
