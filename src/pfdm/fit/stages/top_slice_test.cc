#include "pfdm/fit/stages/top_slice.h"

#include <cmath>
#include <random>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();

// A ring of radius r about the z axis at height z, from angle `from` over
// `span` radians: a contour with `noise` in its plane and a fifth of it
// across (the plane's own error).
void AddRing(double z, double r, double from, double span, double noise,
             std::mt19937* random, std::vector<Eigen::Vector3d>* points) {
  std::normal_distribution<double> gauss(0.0, noise);
  for (int k = 0; k < 40; ++k) {
    const double angle = from + span * k / 40.0;
    points->push_back(
        Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), z) +
        Eigen::Vector3d(gauss(*random), gauss(*random), 0.2 * gauss(*random)));
  }
}

// Nine short-axis slices 10 mm apart, 0.5 mm noise: a slice on top.
std::vector<Eigen::Vector3d> Stack(std::mt19937* random) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 9; ++k) {
    AddRing(10.0 * k, 10.0 + 2.0 * k, -M_PI, 2.0 * M_PI, 0.5, random, &points);
  }
  return points;
}

TEST(TopSliceTest, AShortAxisStackEndsInASlice) {
  std::mt19937 random(1);
  const TopSlice top =
      FindTopSlice(Stack(&random), kOrigin, Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(top.found);
  EXPECT_EQ(top.points, 40);
  EXPECT_NEAR(top.rms_mm, 0.1, 0.05);  // The noise across the plane.
  EXPECT_LT(top.tilt_deg, 3.0);
  EXPECT_EQ(top.sectors, kTopSectors);
}

// The fitted axis 12 degrees from the slices' normal: the top band holds
// part of the top ring only, which still lies on its plane.
TEST(TopSliceTest, AxisTiltedFromTheSlices) {
  std::mt19937 random(2);
  const Eigen::Vector3d axis =
      Eigen::AngleAxisd(12.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
      Eigen::Vector3d::UnitZ();
  const TopSlice top = FindTopSlice(Stack(&random), kOrigin, axis);
  EXPECT_TRUE(top.found);
  EXPECT_LT(top.points, 40);
  EXPECT_NEAR(top.tilt_deg, 12.0, 3.0);
}

// A basal ring cut by the outflow tract (90 degrees missing) is still a
// slice; half a ring, or three long-axis planes reaching 8 mm above the
// top slice, are not.
TEST(TopSliceTest, WhatIsNotAllRound) {
  std::mt19937 random(3);
  std::vector<Eigen::Vector3d> cut = Stack(&random);
  cut.resize(8 * 40);
  AddRing(80.0, 26.0, -M_PI, 1.5 * M_PI, 0.5, &random, &cut);
  EXPECT_TRUE(FindTopSlice(cut, kOrigin, Eigen::Vector3d::UnitZ()).found);

  std::vector<Eigen::Vector3d> half = Stack(&random);
  half.resize(8 * 40);
  AddRing(80.0, 26.0, -M_PI, M_PI, 0.5, &random, &half);
  const TopSlice open = FindTopSlice(half, kOrigin, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(open.found);
  EXPECT_LE(open.sectors, 7);

  // Each long-axis plane's contour runs up the wall on both sides to 88 mm.
  std::vector<Eigen::Vector3d> views = Stack(&random);
  for (int plane = 0; plane < 3; ++plane) {
    const double angle = M_PI * plane / 3.0;
    for (int side : {-1, 1}) {
      for (double z = 0.0; z <= 88.0; z += 1.0) {
        const double r = side * (10.0 + 0.2 * z);
        views.push_back({r * std::cos(angle), r * std::sin(angle), z});
      }
    }
  }
  const TopSlice tops = FindTopSlice(views, kOrigin, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(tops.found);
  EXPECT_GT(tops.rms_mm, kTopPlaneRmsMm);
}

// Few points fill fewer sectors by chance: E - 2 sd of the count a whole
// ring's n random points fill, within 7-9.
TEST(TopSliceTest, FewPointsNeedFewerSectors) {
  EXPECT_EQ(NeededTopSectors(4), kMinSparseTopSectors);
  EXPECT_EQ(NeededTopSectors(16), 7);  // 9.0 +- 1.1 filled.
  EXPECT_EQ(NeededTopSectors(24), 8);  // 10.5 +- 1.0.
  EXPECT_EQ(NeededTopSectors(40), kMinTopSectors);
  EXPECT_EQ(NeededTopSectors(1000), kMinTopSectors);
}

// A top slice of 16 points at random angles all round (both walls' 8 each,
// as the LV phantom's 150 contour points a frame leave them) on a stack:
// 9 sectors were needed and about a third of such slices filled fewer.  Over
// 100 draws every slice is found; 30 of them fill fewer than 9.
TEST(TopSliceTest, ASparseSliceIsStillASlice) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  int found = 0, under_nine = 0;
  for (int draw = 0; draw < 100; ++draw) {
    std::vector<Eigen::Vector3d> points = Stack(&random);
    points.resize(8 * 40);
    for (int k = 0; k < 16; ++k) {
      const double a = angle(random), r = k % 2 == 0 ? 24.0 : 32.0;
      points.push_back({r * std::cos(a), r * std::sin(a), 80.0});
    }
    const TopSlice top =
        FindTopSlice(points, kOrigin, Eigen::Vector3d::UnitZ());
    EXPECT_EQ(top.needed_sectors, 7);
    found += top.found;
    under_nine += top.sectors < kMinTopSectors;
  }
  EXPECT_EQ(found, 100);
  EXPECT_GT(under_nine, 20);
}

// Tags filling the wall's height: the top band is 5 mm thick, no plane.
TEST(TopSliceTest, TagsFillTheHeight) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Eigen::Vector3d> tags;
  for (int k = 0; k < 3000; ++k) {
    const double z = 80.0 * uniform(random);
    const double angle = 2.0 * M_PI * uniform(random);
    const double r = 10.0 + 0.2 * z + 8.0 * uniform(random);
    tags.push_back({r * std::cos(angle), r * std::sin(angle), z});
  }
  const TopSlice top = FindTopSlice(tags, kOrigin, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(top.found);
  EXPECT_NEAR(top.rms_mm, 5.0 / std::sqrt(12.0), 0.2);
}

// Too few points for a plane: nothing found, no crash.
TEST(TopSliceTest, TooFewPoints) {
  const std::vector<Eigen::Vector3d> few = {
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_FALSE(FindTopSlice(few, kOrigin, Eigen::Vector3d::UnitZ()).found);
  EXPECT_FALSE(FindTopSlice({}, kOrigin, Eigen::Vector3d::UnitZ()).found);
}

// A solid whose data end at a slice lifts its mid-wall's rim by its lowest
// wall's drop (TestShell's endocardium at u_max = pi/6: h/2 sin(pi/6)),
// TopIsSlice reading the stack about the model's axis through its centre.
// A surface, or a top that is no slice, keeps it.
TEST(TopSliceTest, ASolidsRimRisesByItsLowestWallsDrop) {
  std::mt19937 random(1);
  const Model shell = TestShell(9);
  ASSERT_TRUE(TopIsSlice(Stack(&random), shell));
  EXPECT_NEAR(RimLift(true, shell), 2.5, 1e-9);
  EXPECT_EQ(RimLift(false, shell), 0.0);
  EXPECT_EQ(RimLift(true, TestSpheroid(9)), 0.0);
}

}  // namespace
}  // namespace pfdm
