// The Gauss-Newton matrix J^T J of a Jacobian Ceres evaluated
// (Problem::Evaluate's CRS matrix), which the integrators' damping, the
// frames' covariance and the Gauss-Newton step all factor, and its product
// with a vector.
#ifndef PFDM_SOLVERS_NORMAL_MATRIX_H_
#define PFDM_SOLVERS_NORMAL_MATRIX_H_

#include "Eigen/Core"
#include "Eigen/SparseCore"
#include "ceres/crs_matrix.h"

namespace pfdm {

// The CRS matrix as Eigen's row-major sparse matrix, without a copy: valid
// while `jacobian` is.
Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> SparseView(
    const ceres::CRSMatrix& jacobian);

// J^T J, dense, of the first `rows` rows of J (all of them when negative or
// more than J has): the data's block when their residuals come first.
Eigen::MatrixXd GaussNewtonMatrix(const ceres::CRSMatrix& jacobian,
                                  int rows = -1);

// J^T J x without forming J^T J (the integrators' power iterations).
Eigen::VectorXd GaussNewtonProduct(const ceres::CRSMatrix& jacobian,
                                   const Eigen::VectorXd& x);

}  // namespace pfdm

#endif  // PFDM_SOLVERS_NORMAL_MATRIX_H_
