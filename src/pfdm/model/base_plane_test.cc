#include "pfdm/model/base_plane.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(BasePlaneTest, LeastSquaresPlaneThroughPoints) {
  // z = 2x + 1: normal along (2, 0, -1).
  std::vector<Eigen::Vector3d> points;
  for (double x : {0.0, 1.0, 3.0}) {
    for (double y : {-1.0, 2.0}) points.emplace_back(x, y, 2 * x + 1);
  }
  const std::optional<BasePlane> plane = FitBasePlane(points);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(
      std::abs(plane->normal.dot(Eigen::Vector3d(2, 0, -1).normalized())), 1.0,
      1e-12);
  EXPECT_NEAR(plane->point.z(), 2 * plane->point.x() + 1, 1e-12);
  EXPECT_EQ(plane->num_points, 6);
  EXPECT_FALSE(FitBasePlane({{0, 0, 0}, {1, 1, 1}}).has_value());
  EXPECT_FALSE(FitBasePlane({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).has_value());
}

// All eigenvalues 0 passed the relative test: six copies of one point were
// a "plane" with an arbitrary normal (issue 14).
TEST(BasePlaneTest, PointsAtOnePlaceDefineNoPlane) {
  const std::vector<Eigen::Vector3d> same(6, Eigen::Vector3d(10, -20, 30));
  EXPECT_FALSE(FitBasePlane(same).has_value());
  std::vector<Eigen::Vector3d> nearly = same;
  nearly[0].x() += 1e-9;
  nearly[1].y() += 1e-9;
  EXPECT_FALSE(FitBasePlane(nearly).has_value());
}

}  // namespace
}  // namespace pfdm
