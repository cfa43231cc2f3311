// Many residual rows replaced by as many rows as they have columns, with the
// same cost, gradient and Gauss-Newton matrix.  A group of 1,024 data points
// has 3,072 rows but only ~20 Jacobian columns; Ceres forms J^T J with its
// generic small-matrix kernels, so handing it the 21-row square-root form,
// built here with Eigen's dense kernels, cuts the linear solver's work ~150x
// while every iterate stays the same.
#ifndef PFDM_FIT_RESIDUALS_SQUARE_ROOT_FORM_H_
#define PFDM_FIT_RESIDUALS_SQUARE_ROOT_FORM_H_

#include <functional>

#include "Eigen/Core"

namespace pfdm {

using RowMajorMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// For a = [J r] (m x (n + 1), m > n), R (n x n, not always triangular), z (n)
// and rho >= 0 with
//   R^T R = J^T J,   R^T z = J^T r,   |z|^2 + rho^2 = |r|^2,
// that is [J r] = Q [R z; 0 rho] for some Q with orthonormal columns.  So
// the rows (z, rho) with Jacobian (R; 0) give a least-squares solver the
// same cost, gradient, Gauss-Newton matrix and model decrease as r with J.
struct SquareRootForm {
  Eigen::MatrixXd r;
  Eigen::VectorXd z;
  double rho = 0.0;
};

SquareRootForm ToSquareRootForm(const RowMajorMatrix& a);

// The same from the Gram matrix a^T a (its lower triangle is read) when the
// caller can form it faster than from a itself; `rows` gives a, for the
// fallback when the Gram matrix is too ill-conditioned to factor.
SquareRootForm SquareRootFormFromGram(
    Eigen::MatrixXd gram, const std::function<RowMajorMatrix()>& rows);

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_SQUARE_ROOT_FORM_H_
