#include "pfdm/fit/residuals/square_root_form.h"

#include <random>

#include "Eigen/Cholesky"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

// The three identities that make (z, rho) with (R; 0) stand in for r with J.
void ExpectSquareRootForm(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  const Eigen::MatrixXd j = a.leftCols(n);
  const Eigen::VectorXd r = a.col(n);
  const SquareRootForm form = ToSquareRootForm(a);
  ASSERT_EQ(form.r.rows(), n);
  ASSERT_EQ(form.r.cols(), n);
  const double scale = j.squaredNorm();
  EXPECT_LT((form.r.transpose() * form.r - j.transpose() * j).norm(),
            1e-12 * scale);
  EXPECT_LT((form.r.transpose() * form.z - j.transpose() * r).norm(),
            1e-12 * std::sqrt(scale) * r.norm());
  EXPECT_NEAR(form.z.squaredNorm() + form.rho * form.rho, r.squaredNorm(),
              1e-12 * r.squaredNorm());
  EXPECT_GE(form.rho, 0.0);
}

RowMajorMatrix Random(int rows, int cols, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  RowMajorMatrix a(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int k = 0; k < cols; ++k) a(i, k) = normal(random);
  }
  return a;
}

TEST(SquareRootFormTest, KeepsCostGradientAndGaussNewtonMatrix) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    ExpectSquareRootForm(Random(60, 8, seed));
  }
  // rho is what J cannot explain: zero when r lies in J's range.
  RowMajorMatrix a = Random(30, 5, 7);
  a.col(4) = a.leftCols(4) * Eigen::Vector4d(1.0, -2.0, 0.5, 3.0);
  EXPECT_NEAR(ToSquareRootForm(a).rho, 0.0, 1e-6);
  ExpectSquareRootForm(a);
}

TEST(SquareRootFormTest, HandlesZeroAndDependentColumns) {
  RowMajorMatrix a = Random(40, 7, 11);
  a.col(2).setZero();  // Like b1 while b0 = 0.
  const SquareRootForm form = ToSquareRootForm(a);
  EXPECT_EQ(form.r.col(2).norm(), 0.0);
  ExpectSquareRootForm(a);
  // A column proportional to another (every point with the same knot
  // weight): J^T J is singular, not just at a zero column.
  a.col(4) = 0.3 * a.col(1);
  ExpectSquareRootForm(a);
}

// A pivot that elimination leaves exactly 0 before a regular one fails
// Eigen's LDLT, which pivots on the diagonal it started with: here the
// copy of column 0 (diagonal 4) comes before column 2 (diagonal 1).  The
// pivoted Cholesky takes it without the QR of the rows.
TEST(SquareRootFormTest, AnExactlyZeroPivotNeedsNoQr) {
  RowMajorMatrix a = RowMajorMatrix::Zero(6, 4);
  a.col(0) << 2.0, 0.0, 0.0, 0.0, 0.0, 0.0;
  a.col(1) = a.col(0);
  a.col(2) << 0.0, 1.0, 0.0, 0.0, 0.0, 0.0;
  a.col(3) << 1.0, -2.0, 3.0, 0.5, 0.0, 1.0;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(4, 4);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  ASSERT_NE(Eigen::LDLT<Eigen::MatrixXd>(gram.topLeftCorner(3, 3)).info(),
            Eigen::Success);
  bool asked_for_rows = false;
  const SquareRootForm form = SquareRootFormFromGram(gram, [&] {
    asked_for_rows = true;
    return a;
  });
  EXPECT_FALSE(asked_for_rows);
  const Eigen::MatrixXd j = a.leftCols(3);
  const Eigen::VectorXd r = a.col(3);
  EXPECT_LT((form.r.transpose() * form.r - j.transpose() * j).norm(), 1e-14);
  EXPECT_LT((form.r.transpose() * form.z - j.transpose() * r).norm(), 1e-14);
  EXPECT_NEAR(form.z.squaredNorm() + form.rho * form.rho, r.squaredNorm(),
              1e-14);
  EXPECT_NEAR(form.rho, std::sqrt(3.0 * 3.0 + 0.5 * 0.5 + 1.0), 1e-14);
}

}  // namespace
}  // namespace pfdm
