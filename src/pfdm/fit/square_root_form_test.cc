#include "pfdm/fit/square_root_form.h"

#include <random>

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

}  // namespace
}  // namespace pfdm
