#include "pfdm/io/partial_rings.h"

#include <cmath>
#include <string>
#include <vector>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An arc of `radius` about (cx, cy) at height z, from angle `from` to `to`
// (radians), n points.
std::vector<Eigen::Vector3d> Arc(double cx, double cy, double z, double radius,
                                 double from, double to, int n) {
  std::vector<Eigen::Vector3d> arc;
  for (int i = 0; i < n; ++i) {
    const double a = from + (to - from) * i / (n - 1);
    arc.emplace_back(cx + radius * std::cos(a), cy + radius * std::sin(a), z);
  }
  return arc;
}

TEST(PartialRingsTest, CircleOfAnArcIsItsOwn) {
  const RingCircle c = FitRingCircle(Arc(3.0, -2.0, 5.0, 14.0, 0.3, 3.6, 20));
  EXPECT_NEAR(c.centre.x(), 3.0, 1e-9);
  EXPECT_NEAR(c.centre.y(), -2.0, 1e-9);
  EXPECT_NEAR(c.centre.z(), 5.0, 1e-9);
  EXPECT_NEAR(c.radius, 14.0, 1e-9);
}

TEST(PartialRingsTest, GapSeenFromAPoint) {
  // A full ring of 36 points leaves 10 degrees; a half ring seen from its
  // centre, 180.
  const auto full = Arc(0, 0, 0, 10.0, 0.0, 2 * kPi * 35 / 36, 36);
  EXPECT_NEAR(LargestGapDeg(full, FitRingCircle(full), {0, 0, 0}), 10.0, 1e-9);
  const auto half = Arc(0, 0, 0, 10.0, 0.0, kPi, 19);
  EXPECT_NEAR(LargestGapDeg(half, FitRingCircle(half), {0, 0, 0}), 180.0, 1e-9);
}

struct Stack {
  std::vector<DataPoint> points;
  std::vector<std::string> contours;
  void Add(const std::string& contour,
           const std::vector<Eigen::Vector3d>& ring) {
    for (const Eigen::Vector3d& p : ring) {
      points.push_back({static_cast<std::int64_t>(points.size()), p});
      contours.push_back(contour);
    }
  }
};

// A ventricle along z, base up: rings of radius 10 (apex) to 25 (base) on
// the axis, and at the top a ring of `top_radius` about (top_x, 0).
Stack VentricleWithTop(double top_x, double top_radius, double top_to) {
  Stack stack;
  stack.Add("SAX_LV_ENDOCARDIAL 5", Arc(0, 0, 0, 10.0, 0, 6.1, 30));
  stack.Add("SAX_LV_ENDOCARDIAL 4", Arc(0, 0, 10, 18.0, 0, 6.1, 40));
  stack.Add("SAX_LV_ENDOCARDIAL 3", Arc(0, 0, 20, 25.0, 0, 6.1, 50));
  stack.Add("LAX_LV_ENDOCARDIAL 8", Arc(0, 0, 15, 20.0, 0, 1.0, 10));
  stack.Add("SAX_LV_ENDOCARDIAL 2",
            Arc(top_x, 0, 30, top_radius, 0, top_to, 25));
  return stack;
}

TEST(PartialRingsTest, OutflowTractRingBesideTheAxisIsLeftOut) {
  // A ring of 14 mm whose centre lies 20 mm off the axis: the axis is
  // outside it.
  Stack stack = VentricleWithTop(20.0, 14.0, 2 * kPi * 0.97);
  std::vector<LeftOutContour> left_out;
  const size_t before = stack.points.size();
  LeaveOutPartialRings(13, stack.contours, &stack.points, &left_out);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out[0].frame, 13);
  EXPECT_EQ(left_out[0].contour, "SAX_LV_ENDOCARDIAL 2");
  EXPECT_EQ(left_out[0].points, 25);
  // Seen from the axis, 14 mm at 20 mm spans 2 asin(14 / 20) = 88.9 deg.
  EXPECT_NEAR(left_out[0].coverage_deg, 88.9, 2.0);
  EXPECT_EQ(stack.points.size(), before - 25);
}

// The slice's epicardial arc round the axis goes with it: the plane holds
// the outflow tract.
TEST(PartialRingsTest, TheSlicesOtherContoursGoWithIt) {
  Stack stack = VentricleWithTop(20.0, 14.0, 2 * kPi * 0.97);
  stack.Add("SAX_LV_EPICARDIAL 2", Arc(0, 0, 30, 32.0, 0, 4.0, 30));
  stack.Add("SAX_LV_EPICARDIAL 3", Arc(0, 0, 20, 33.0, 0, 4.0, 30));
  std::vector<LeftOutContour> left_out;
  LeaveOutPartialRings(6, stack.contours, &stack.points, &left_out);
  ASSERT_EQ(left_out.size(), 2u);
  EXPECT_EQ(left_out[0].contour, "SAX_LV_ENDOCARDIAL 2");
  EXPECT_EQ(left_out[1].contour, "SAX_LV_EPICARDIAL 2");
  // The arc spans 4 radians about the axis.
  EXPECT_NEAR(left_out[1].coverage_deg, 4.0 * 180.0 / kPi, 1.0);
  EXPECT_EQ(stack.points.size(), 130u + 30u);
}

TEST(PartialRingsTest, RingsAndArcsRoundTheAxisAreKept) {
  std::vector<LeftOutContour> left_out;
  // A full basal ring a third of its radius off the axis (biv-me's basal
  // rings: 0.27-0.51 radii).
  Stack offset = VentricleWithTop(9.0, 27.0, 2 * kPi * 0.97);
  LeaveOutPartialRings(0, offset.contours, &offset.points, &left_out);
  // An epicardial free-wall arc of 225 degrees about the axis.
  Stack arc = VentricleWithTop(0.0, 28.0, 225.0 * kPi / 180.0);
  LeaveOutPartialRings(0, arc.contours, &arc.points, &left_out);
  EXPECT_TRUE(left_out.empty());
  EXPECT_EQ(offset.points.size(), 155u);
  EXPECT_EQ(arc.points.size(), 155u);
}

// Three rings cannot tell the base's end: all are kept.
TEST(PartialRingsTest, ThreeRingsAreLeftAsTheyAre) {
  Stack stack;
  stack.Add("SAX_LV_ENDOCARDIAL 4", Arc(0, 0, 10, 18.0, 0, 6.1, 40));
  stack.Add("SAX_LV_ENDOCARDIAL 3", Arc(0, 0, 20, 25.0, 0, 6.1, 50));
  stack.Add("SAX_LV_ENDOCARDIAL 2", Arc(20.0, 0, 30, 14.0, 0, 6.1, 25));
  std::vector<LeftOutContour> left_out;
  LeaveOutPartialRings(0, stack.contours, &stack.points, &left_out);
  EXPECT_TRUE(left_out.empty());
  EXPECT_EQ(stack.points.size(), 115u);
}

TEST(PartialRingsTest, ApicalEndIsNotJudged) {
  // The same outflow-tract ring at the narrow end is the apex's side: kept.
  Stack stack;
  stack.Add("SAX_LV_ENDOCARDIAL 2", Arc(0, 0, 30, 25.0, 0, 6.1, 50));
  stack.Add("SAX_LV_ENDOCARDIAL 3", Arc(0, 0, 20, 18.0, 0, 6.1, 40));
  stack.Add("SAX_LV_ENDOCARDIAL 4", Arc(0, 0, 10, 10.0, 0, 6.1, 30));
  stack.Add("SAX_LV_ENDOCARDIAL 5", Arc(8.0, 0, 0, 3.0, 0, 6.1, 12));
  std::vector<LeftOutContour> left_out;
  LeaveOutPartialRings(0, stack.contours, &stack.points, &left_out);
  EXPECT_TRUE(left_out.empty());
  EXPECT_EQ(stack.points.size(), 132u);
}

}  // namespace
}  // namespace pfdm
