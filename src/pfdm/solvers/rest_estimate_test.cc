// The rest estimate against the closed form of a linear least squares.
#include "pfdm/solvers/rest_estimate.h"

#include <optional>
#include <vector>

#include "Eigen/Dense"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

ceres::CRSMatrix ToCrs(const Eigen::MatrixXd& dense) {
  ceres::CRSMatrix crs;
  crs.num_rows = static_cast<int>(dense.rows());
  crs.num_cols = static_cast<int>(dense.cols());
  crs.rows.push_back(0);
  for (int r = 0; r < crs.num_rows; ++r) {
    for (int c = 0; c < crs.num_cols; ++c) {
      if (dense(r, c) == 0.0) continue;
      crs.cols.push_back(c);
      crs.values.push_back(dense(r, c));
    }
    crs.rows.push_back(static_cast<int>(crs.cols.size()));
  }
  return crs;
}

// Residuals r = J q - b with columns a thousand times apart in scale (mm
// against radians): at q the force is g = J^T (J q - b) and the distance to
// rest |J (q - q*)|, q* the least-squares solution, to 1e-9 relative.
TEST(RestEstimateTest, DistanceIsTheResidualsMoveToTheLeastSquaresPoint) {
  Eigen::MatrixXd j(6, 3);
  j << 1, 0.5, 0, 0.2, 1, 0.1, 0, 0.3, 1, 1, 1, 1, 0.5, -1, 0.2, 0, 0, 2;
  j.col(2) *= 1e3;
  const Eigen::VectorXd b = (Eigen::VectorXd(6) << 1, 2, 3, 4, 5, 6).finished();
  const Eigen::VectorXd q_star = j.colPivHouseholderQr().solve(b);
  const Eigen::VectorXd q = q_star + Eigen::Vector3d(0.3, -0.7, 2e-4);
  const Eigen::VectorXd g = j.transpose() * (j * q - b);
  const std::optional<RestEstimate> estimate =
      RestEstimate::FromJacobian(ToCrs(j));
  ASSERT_TRUE(estimate.has_value());
  const double expected = (j * (q - q_star)).norm();
  EXPECT_NEAR(estimate->DistanceToRest({g[0], g[1], g[2]}) / expected, 1.0,
              1e-9);
  EXPECT_EQ(estimate->DistanceToRest({0.0, 0.0, 0.0}), 0.0);
}

// A column no residual sees leaves H singular, and a problem past the dense
// limit is not factored: no estimate either way.
TEST(RestEstimateTest, NoEstimateForASingularOrLargeProblem) {
  Eigen::MatrixXd j = Eigen::MatrixXd::Identity(3, 3);
  j(2, 2) = 0.0;
  EXPECT_FALSE(RestEstimate::FromJacobian(ToCrs(j)).has_value());
  const int n = RestEstimate::kMaxColumns + 1;
  EXPECT_FALSE(
      RestEstimate::FromJacobian(ToCrs(Eigen::MatrixXd::Identity(n, n)))
          .has_value());
}

}  // namespace
}  // namespace pfdm
