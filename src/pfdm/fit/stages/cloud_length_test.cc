#include "pfdm/fit/stages/cloud_length.h"

#include <cmath>
#include <random>
#include <vector>

#include "Eigen/Geometry"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

// 4,000 normal points of standard deviations `sds` along the axes of
// `rotation`.
std::vector<Eigen::Vector3d> Cloud(const Eigen::Vector3d& sds,
                                   const Eigen::Matrix3d& rotation) {
  std::mt19937 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Vector3d p(normal(random), normal(random), normal(random));
    points.push_back(rotation * p.cwiseProduct(sds) +
                     Eigen::Vector3d(10, -4, 7));
  }
  return points;
}

TEST(CloudLengthTest, AnElongatedCloudsLengthIsItsLargestSpread) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized())
          .toRotationMatrix();
  const CloudLength length = LengthOf(Cloud({10, 12, 24}, rotation));
  EXPECT_NEAR(length.ratio, 2.0, 0.06);
  EXPECT_TRUE(length.Elongated());
  EXPECT_LT(length.DegreesFrom(rotation.col(2)), 2.0);
  EXPECT_LT(length.DegreesFrom(-rotation.col(2)), 2.0);
  EXPECT_NEAR(length.DegreesFrom(rotation.col(0)), 90.0, 2.0);
  EXPECT_FALSE(length.Across(rotation.col(2)));
  EXPECT_TRUE(length.Across(rotation.col(1)));
  // 44 and 46 degrees from the length, in the plane of axes 1 and 3.
  const double near = 44.0 * M_PI / 180.0, far = 46.0 * M_PI / 180.0;
  const Eigen::Vector3d axis = length.axis;
  const Eigen::Vector3d side = axis.unitOrthogonal();
  EXPECT_FALSE(length.Across(std::cos(near) * axis + std::sin(near) * side));
  EXPECT_TRUE(length.Across(std::cos(far) * axis + std::sin(far) * side));
}

// Nothing lies across a squat cloud: no direction is clearly its longest.
TEST(CloudLengthTest, ASquatCloudHasNoLengthToLieAcross) {
  const CloudLength length =
      LengthOf(Cloud({20, 21, 24}, Eigen::Matrix3d::Identity()));
  EXPECT_NEAR(length.ratio, 24.0 / 21.0, 0.05);
  EXPECT_FALSE(length.Elongated());
  EXPECT_FALSE(length.Across(Eigen::Vector3d::UnitX()));
}

}  // namespace
}  // namespace pfdm
