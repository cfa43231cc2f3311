#include "pfdm/fit/linear_node_cost.h"

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

namespace {

// The rows `projection` (m x 3) of x_g + R d - data.
ceres::CostFunction* MakeProjectedPointCost(const Eigen::MatrixXd& projection,
                                            const Eigen::Vector3d& global_point,
                                            const Eigen::Matrix3d& rotation,
                                            const ShapeWeights& shape,
                                            const Eigen::Vector3d& data) {
  std::vector<Eigen::MatrixXd> blocks;
  const Eigen::MatrixXd moved = projection * rotation;
  for (int k = 0; k < shape.count; ++k) {
    blocks.push_back(shape.weight[k] * moved);
  }
  return new LinearNodeCost(projection * (global_point - data),
                            std::move(blocks));
}

}  // namespace

ceres::CostFunction* MakeLocalPointCost(const Eigen::Vector3d& global_point,
                                        const Eigen::Matrix3d& rotation,
                                        const ShapeWeights& shape,
                                        const Eigen::Vector3d& data) {
  return MakeProjectedPointCost(Eigen::Matrix3d::Identity(), global_point,
                                rotation, shape, data);
}

ceres::CostFunction* MakeLocalSurfaceCost(const Eigen::Vector3d& global_point,
                                          const Eigen::Matrix3d& rotation,
                                          const ShapeWeights& shape,
                                          const Eigen::Vector3d& data,
                                          const Eigen::Vector3d& normal) {
  return MakeProjectedPointCost(normal.transpose(), global_point, rotation,
                                shape, data);
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
