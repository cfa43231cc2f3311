#include "pfdm/solvers/normal_matrix.h"

#include "Eigen/Dense"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

// A 4 x 3 Jacobian with an empty row and a column that only its last row
// touches, in CRS.
ceres::CRSMatrix SmallJacobian() {
  ceres::CRSMatrix j;
  j.num_rows = 4;
  j.num_cols = 3;
  j.rows = {0, 2, 3, 3, 6};
  j.cols = {0, 1, 1, 0, 1, 2};
  j.values = {1.0, 2.0, -3.0, 0.5, 4.0, -1.5};
  return j;
}

Eigen::MatrixXd Dense(const ceres::CRSMatrix& j) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(j.num_rows, j.num_cols);
  for (int r = 0; r < j.num_rows; ++r) {
    for (int k = j.rows[r]; k < j.rows[r + 1]; ++k) {
      dense(r, j.cols[k]) = j.values[k];
    }
  }
  return dense;
}

TEST(NormalMatrixTest, SparseViewReadsTheRows) {
  const ceres::CRSMatrix j = SmallJacobian();
  EXPECT_EQ(Eigen::MatrixXd(SparseView(j)), Dense(j));
}

TEST(NormalMatrixTest, IsJTransposeJOfAllOrTheFirstRows) {
  const ceres::CRSMatrix j = SmallJacobian();
  const Eigen::MatrixXd dense = Dense(j);
  EXPECT_TRUE(GaussNewtonMatrix(j).isApprox(dense.transpose() * dense, 1e-15));
  EXPECT_TRUE(
      GaussNewtonMatrix(j, 99).isApprox(dense.transpose() * dense, 1e-15));
  const Eigen::MatrixXd top = dense.topRows(2);
  const Eigen::MatrixXd first_two = GaussNewtonMatrix(j, 2);
  EXPECT_TRUE(first_two.isApprox(top.transpose() * top, 1e-15));
  EXPECT_EQ(first_two(2, 2), 0.0);  // Only the last row touches column 2.
  EXPECT_EQ(GaussNewtonMatrix(j, 0), Eigen::MatrixXd::Zero(3, 3));
}

TEST(NormalMatrixTest, ProductIsJTransposeJTimesX) {
  const ceres::CRSMatrix j = SmallJacobian();
  const Eigen::MatrixXd dense = Dense(j);
  const Eigen::Vector3d x(0.7, -1.3, 2.0);
  EXPECT_TRUE(GaussNewtonProduct(j, x).isApprox(dense.transpose() * (dense * x),
                                                1e-15));
}

}  // namespace
}  // namespace pfdm
