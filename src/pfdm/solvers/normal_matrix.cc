#include "pfdm/solvers/normal_matrix.h"

#include <algorithm>

namespace pfdm {

Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> SparseView(
    const ceres::CRSMatrix& jacobian) {
  return Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
      jacobian.num_rows, jacobian.num_cols,
      static_cast<Eigen::Index>(jacobian.values.size()), jacobian.rows.data(),
      jacobian.cols.data(), jacobian.values.data());
}

Eigen::MatrixXd GaussNewtonMatrix(const ceres::CRSMatrix& jacobian, int rows) {
  const auto j = SparseView(jacobian);
  const int kept =
      rows < 0 ? jacobian.num_rows : std::min(rows, jacobian.num_rows);
  const auto top = j.topRows(kept);
  return Eigen::SparseMatrix<double>(top.transpose() * top).toDense();
}

Eigen::VectorXd GaussNewtonProduct(const ceres::CRSMatrix& jacobian,
                                   const Eigen::VectorXd& x) {
  const auto j = SparseView(jacobian);
  const Eigen::VectorXd y = j * x;
  return j.transpose() * y;
}

}  // namespace pfdm
