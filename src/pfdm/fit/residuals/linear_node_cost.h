// A residual linear in nodal displacement vectors: the local field's data
// terms and its stiffness (local_fit.h).
#ifndef PFDM_FIT_RESIDUALS_LINEAR_NODE_COST_H_
#define PFDM_FIT_RESIDUALS_LINEAR_NODE_COST_H_

#include <vector>

#include "Eigen/Core"
#include "ceres/cost_function.h"
#include "pfdm/fit/residuals/square_root_form.h"
#include "pfdm/model/local_field.h"

namespace pfdm {

// r = b + sum_k A_k q_k, with q_k the k-th parameter block (3 numbers, a
// node's displacement in the model frame) and A_k an m x 3 matrix, so
// dr/dq_k = A_k: the Jacobian is constant and each residual touches only
// the nodes it names, which keeps the problem as sparse as the grid.
class LinearNodeCost : public ceres::CostFunction {
 public:
  // Every A_k has offset.size() rows.
  LinearNodeCost(Eigen::VectorXd offset, std::vector<Eigen::MatrixXd> blocks);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::VectorXd offset_;
  std::vector<Eigen::MatrixXd> blocks_;
};

// A data point on the whole model, x = x_g(u, v) + R d(u, v) with the global
// part held:
//   r = x_g + R sum_k S_k q_k - data            (3 rows),
//   r = n . (x_g + R sum_k S_k q_k - data)      (1 row, with a normal n),
// S_k = shape.weight[k], the blocks shape.node[k] in order.  Points on
// contours take the plane row, as in the global fit: their material point
// is only where the global surface was closest.
ceres::CostFunction* MakeLocalPointCost(const Eigen::Vector3d& global_point,
                                        const Eigen::Matrix3d& rotation,
                                        const ShapeWeights& shape,
                                        const Eigen::Vector3d& data);
ceres::CostFunction* MakeLocalSurfaceCost(const Eigen::Vector3d& global_point,
                                          const Eigen::Matrix3d& rotation,
                                          const ShapeWeights& shape,
                                          const Eigen::Vector3d& data,
                                          const Eigen::Vector3d& normal);

// [A_0 .. A_{k-1} b]: the cost's matrices side by side and its offset last.
ceres::CostFunction* MakeLinearNodeCost(const RowMajorMatrix& rows);

// The rows [S_0 P R .. S_{count-1} P R  P (x_g - data)] of a data point's
// cost below (P = I, or n^T with a normal), for stacking the points of one
// element into one residual block in square-root form (local_fit.cc).
// At most 3 rows of 4 nodes' columns and the residual's, off the heap.
using LocalRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                Eigen::RowMajor, 3, 13>;
LocalRows LocalPointRows(const Eigen::Vector3d& global_point,
                         const Eigen::Matrix3d& rotation,
                         const ShapeWeights& shape, const Eigen::Vector3d& data,
                         const Eigen::Vector3d* normal);

// r = sqrt_weight sum_k c_k q_k (3 rows): a finite difference of the nodal
// vectors (membrane: c = (1, -1); thin plate: (1, -2, 1) or the mixed
// (1, -1, -1, 1)).
ceres::CostFunction* MakeNodeDifferenceCost(
    double sqrt_weight, const std::vector<double>& coefficients);

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_LINEAR_NODE_COST_H_
