#include "pfdm/fit/residuals/linear_node_cost.h"

#include <utility>

namespace pfdm {

LinearNodeCost::LinearNodeCost(Eigen::VectorXd offset,
                               std::vector<Eigen::MatrixXd> blocks)
    : offset_(std::move(offset)), blocks_(std::move(blocks)) {
  set_num_residuals(static_cast<int>(offset_.size()));
  for (size_t k = 0; k < blocks_.size(); ++k) {
    mutable_parameter_block_sizes()->push_back(3);
  }
}

bool LinearNodeCost::Evaluate(double const* const* parameters,
                              double* residuals, double** jacobians) const {
  Eigen::Map<Eigen::VectorXd> r(residuals, offset_.size());
  r = offset_;
  for (size_t k = 0; k < blocks_.size(); ++k) {
    r += blocks_[k] * Eigen::Vector3d::Map(parameters[k]);
    if (jacobians != nullptr && jacobians[k] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
          jacobians[k], offset_.size(), 3) = blocks_[k];
    }
  }
  return true;
}

ceres::CostFunction* MakeLinearNodeCost(const RowMajorMatrix& rows) {
  std::vector<Eigen::MatrixXd> blocks;
  const int count = static_cast<int>(rows.cols() - 1) / 3;
  for (int k = 0; k < count; ++k) blocks.push_back(rows.middleCols<3>(3 * k));
  return new LinearNodeCost(rows.col(rows.cols() - 1), std::move(blocks));
}

LocalRows LocalPointRows(const Eigen::Vector3d& global_point,
                         const Eigen::Matrix3d& rotation,
                         const ShapeWeights& shape, const Eigen::Vector3d& data,
                         const Eigen::Vector3d* normal) {
  using Projection =
      Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor, 3, 3>;
  const Projection projection = normal != nullptr
                                    ? Projection(normal->transpose())
                                    : Projection(Eigen::Matrix3d::Identity());
  LocalRows rows(projection.rows(), 3 * shape.count + 1);
  const Projection moved = projection * rotation;
  for (int k = 0; k < shape.count; ++k) {
    rows.middleCols<3>(3 * k) = shape.weight[k] * moved;
  }
  rows.col(3 * shape.count) = projection * (global_point - data);
  return rows;
}

ceres::CostFunction* MakeLocalPointCost(const Eigen::Vector3d& global_point,
                                        const Eigen::Matrix3d& rotation,
                                        const ShapeWeights& shape,
                                        const Eigen::Vector3d& data) {
  return MakeLinearNodeCost(
      LocalPointRows(global_point, rotation, shape, data, nullptr));
}

ceres::CostFunction* MakeLocalSurfaceCost(const Eigen::Vector3d& global_point,
                                          const Eigen::Matrix3d& rotation,
                                          const ShapeWeights& shape,
                                          const Eigen::Vector3d& data,
                                          const Eigen::Vector3d& normal) {
  return MakeLinearNodeCost(
      LocalPointRows(global_point, rotation, shape, data, &normal));
}

ceres::CostFunction* MakeNodeDifferenceCost(
    double sqrt_weight, const std::vector<double>& coefficients) {
  std::vector<Eigen::MatrixXd> blocks;
  for (double c : coefficients) {
    blocks.push_back(sqrt_weight * c * Eigen::Matrix3d::Identity());
  }
  return new LinearNodeCost(Eigen::Vector3d::Zero(), std::move(blocks));
}

}  // namespace pfdm
