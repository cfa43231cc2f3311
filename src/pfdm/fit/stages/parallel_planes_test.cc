#include "pfdm/fit/stages/parallel_planes.h"

#include <cmath>
#include <random>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

const Eigen::Matrix3d& Tilt() {
  static const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized())
          .toRotationMatrix();
  return tilt;
}

// Rings of radius 25 mm at these heights along the tilted z, `per_ring`
// points each, `noise_mm` along the normal.
std::vector<Eigen::Vector3d> Rings(const std::vector<double>& heights,
                                   int per_ring, double noise_mm,
                                   std::mt19937* random) {
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::normal_distribution<double> noise(0.0, noise_mm);
  std::vector<Eigen::Vector3d> points;
  for (double z : heights) {
    for (int i = 0; i < per_ring; ++i) {
      const double a = angle(*random);
      points.push_back(Tilt() * Eigen::Vector3d(25 * std::cos(a),
                                                25 * std::sin(a),
                                                z + noise(*random)) +
                       Eigen::Vector3d(10, -40, 200));
    }
  }
  return points;
}

double DegreesOff(const Eigen::Vector3d& normal) {
  return std::acos(std::min(1.0, std::abs(normal.dot(Tilt().col(2))))) * 180 /
         kPi;
}

TEST(ParallelPlanesTest, FindsThreeNoisyShortAxisPlanes) {
  std::mt19937 random(3);
  const auto planes = FindParallelPlanes(Rings({0, 20, 40}, 300, 0.3, &random));
  ASSERT_TRUE(planes.has_value());
  EXPECT_EQ(planes->count, 3);
  EXPECT_GT(planes->fraction, 0.95);
  EXPECT_LT(DegreesOff(planes->normal), 0.5);
}

// A stack of 9 with long-axis contours (two planes through the axis, each
// holding three times a slice's points; 40 % of all): the stack's planes
// hold most points, and its normal wins.
TEST(ParallelPlanesTest, FindsAStackBesideLongAxisContours) {
  std::mt19937 random(4);
  std::vector<Eigen::Vector3d> points =
      Rings({0, 10, 20, 30, 40, 50, 60, 70, 80}, 60, 0.0, &random);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < 360; ++i) {
    // The outline of a spheroid cut through its axis, apex at z = -5.
    const double along = -5 + 90 * uniform(random);
    const double radius =
        (i % 2 ? 25 : -25) * std::sqrt(1 - std::pow((85 - along) / 90, 2));
    const Eigen::Vector3d p = i % 4 < 2 ? Eigen::Vector3d(radius, 0, along)
                                        : Eigen::Vector3d(0, radius, along);
    points.push_back(Tilt() * p + Eigen::Vector3d(10, -40, 200));
  }
  const auto planes = FindParallelPlanes(points);
  ASSERT_TRUE(planes.has_value());
  EXPECT_EQ(planes->count, 9);
  // The slices' 60 %, and the long-axis points within 1 mm of them (8 %).
  EXPECT_NEAR(planes->fraction, 0.68, 0.03);
  EXPECT_LT(DegreesOff(planes->normal), 0.1);
}

// Tags of a segment spread along the axis, a blob, one plane, too few
// points: no planes.
TEST(ParallelPlanesTest, NoneInACloudOrASinglePlane) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 40.0);
  std::vector<double> heights;
  for (int i = 0; i < 400; ++i) heights.push_back(uniform(random));
  EXPECT_FALSE(FindParallelPlanes(Rings(heights, 5, 0.5, &random)));
  std::normal_distribution<double> normal(0.0, 20.0);
  std::vector<Eigen::Vector3d> blob;
  for (int i = 0; i < 1000; ++i) {
    blob.emplace_back(normal(random), normal(random), normal(random));
  }
  EXPECT_FALSE(FindParallelPlanes(blob));
  EXPECT_FALSE(FindParallelPlanes(Rings({10}, 500, 0.2, &random)));
  EXPECT_FALSE(FindParallelPlanes(Rings({0, 20}, 10, 0.0, &random)));
}

}  // namespace
}  // namespace pfdm
