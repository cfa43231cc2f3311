#include "pfdm/report/rv_insertion.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A sphere of radius 40 mm about the origin, turned 30 degrees about +z
// and moved: the model's v = 0 lies at world angle 30 degrees.
Model TurnedSphere() {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = values[kA3] = 0.8;
  Model model = Model::Uniform(ModelConfig::Paper(17), values);
  model.state.center = {5.0, -3.0, 2.0};
  model.state.quaternion = {std::cos(kPi / 12), 0.0, 0.0, std::sin(kPi / 12)};
  return model;
}

// A world point at model longitude v, sin u = s, distance r from the
// centre.
Eigen::Vector3d At(double v, double s, double r = 40.0) {
  const double c = std::sqrt(1 - s * s);
  const double a = v + kPi / 6;
  return Eigen::Vector3d(5.0, -3.0, 2.0) +
         r * Eigen::Vector3d(c * std::cos(a), c * std::sin(a), s);
}

TEST(RvInsertionTest, NearestLongitudeIsTheModelsV) {
  const Model model = TurnedSphere();
  const MaterialLongitude on = NearestLongitude(model, At(0.3, 0.0, 50.0));
  EXPECT_NEAR(on.v, 0.3, 1e-6);
  EXPECT_NEAR(on.height_fraction, 2.0 / 3.0, 1e-6);  // sin u 0 of -1..0.5.
  EXPECT_NEAR(on.distance_mm, 10.0, 1e-6);
  EXPECT_NEAR(NearestLongitude(model, At(-3.1, -0.6, 35.0)).v, -3.1, 1e-6);
  // Wraps into [-pi, pi).
  EXPECT_NEAR(NearestLongitude(model, At(3.2, 0.2)).v, 3.2 - 2 * kPi, 1e-6);
}

TEST(RvInsertionTest, LabelledInsertionsSetTheAnchorAndTheSense) {
  const Model model = TurnedSphere();
  RvInsertion insertion;
  insertion.source = "--rv_insertion";
  insertion.anterior = {At(1.0, 0.2)};
  insertion.inferior = {At(1.0 - 2.0, 0.2)};
  const RegionLayout layout = AnatomicalLayout(model, insertion);
  EXPECT_TRUE(layout.anatomical);
  EXPECT_EQ(layout.anchor, "--rv_insertion");
  EXPECT_NEAR(layout.anchor_v, 1.0, 1e-6);
  EXPECT_NEAR(layout.inferior_v, -1.0, 1e-6);
  EXPECT_EQ(layout.direction, -1.0);
  EXPECT_EQ(layout.anterior_points, 1);
  EXPECT_EQ(layout.inferior_points, 1);
  // Mirrored data: the septum the other way, and so the segments.
  insertion.inferior = {At(1.0 + 2.0, 0.2)};
  EXPECT_EQ(AnatomicalLayout(model, insertion).direction, 1.0);
  // The anterior alone: the septum clockwise seen from the base.
  insertion.inferior.clear();
  const RegionLayout anterior = AnatomicalLayout(model, insertion);
  EXPECT_TRUE(anterior.anatomical);
  EXPECT_EQ(anterior.direction, -1.0);
  EXPECT_TRUE(std::isnan(anterior.inferior_v));
}

// RV_INSERT: two points per slice, in no order; the anterior one of each
// pair is that from which the septum runs clockwise seen from the base.
// The apical slice's pair, nearer together, does not move the anchor.
TEST(RvInsertionTest, PairsOfUnlabelledPointsAreSortedBySlice) {
  const Model model = TurnedSphere();
  RvInsertion insertion;
  insertion.source = "RV_INSERT points";
  // Per slice (sin u), the anterior and the inferior insertion's v; `sign`
  // -1 mirrors them.
  auto points = [](double sign) {
    const double pairs[][3] = {{0.3, 0.9, 0.9 - 2.1},
                               {0.0, 1.1, 1.1 - 2.0},
                               {-0.3, 1.0, 1.0 - 1.9},
                               {-0.8, 0.2, -0.3}};
    std::vector<Eigen::Vector3d> out;
    for (int k = 0; k < 4; ++k) {
      // In no order: the inferior first on every other slice.
      const int first = k % 2 == 0 ? 1 : 2;
      out.push_back(At(sign * pairs[k][first], pairs[k][0]));
      out.push_back(At(sign * pairs[k][3 - first], pairs[k][0]));
    }
    return out;
  };
  insertion.unlabelled = points(1.0);
  const RegionLayout layout = AnatomicalLayout(model, insertion);
  ASSERT_TRUE(layout.anatomical) << layout.anchor;
  EXPECT_NEAR(layout.anchor_v, 1.0, 1e-3);
  EXPECT_NEAR(layout.inferior_v, (-1.2 - 0.9 - 0.9) / 3, 0.01);
  EXPECT_EQ(layout.direction, -1.0);
  EXPECT_EQ(layout.anterior_points, 3);
  EXPECT_EQ(layout.inferior_points, 3);
  // Their mirror image: the labels follow the handedness, so the anchor
  // falls on the mirrored inferior insertion (v = 0.9, 1.2, 0.9).
  insertion.unlabelled = points(-1.0);
  const RegionLayout mirrored = AnatomicalLayout(model, insertion);
  EXPECT_NEAR(mirrored.anchor_v, 1.0, 0.01);
  EXPECT_NEAR(mirrored.inferior_v, -1.0, 1e-3);
}

TEST(RvInsertionTest, WithoutAnInsertionTheLayoutSaysWhy) {
  const Model model = TurnedSphere();
  const RegionLayout none = AnatomicalLayout(model, std::nullopt);
  EXPECT_FALSE(none.anatomical);
  EXPECT_EQ(none.anchor, "no RV insertion given");
  EXPECT_EQ(none.anchor_v, RegionLayout().anchor_v);
  RvInsertion odd;
  odd.source = "3 RV_INSERT points of GPFile_000.txt";
  odd.unlabelled = {At(1.0, 0.0), At(-1.0, 0.0), At(1.0, -0.3)};
  const RegionLayout unpaired = AnatomicalLayout(model, odd);
  EXPECT_FALSE(unpaired.anatomical);
  EXPECT_EQ(unpaired.anchor,
            "3 RV_INSERT points of GPFile_000.txt: 3 RV insertion points, not "
            "one anterior and one inferior per slice");
  // A point off the LV (the sphere's axis is 60 mm long here).
  RvInsertion far;
  far.source = "--rv_insertion";
  far.anterior = {At(1.0, 0.0, 80.0)};
  const RegionLayout off = AnatomicalLayout(model, far);
  EXPECT_FALSE(off.anatomical);
  EXPECT_EQ(off.anchor,
            "--rv_insertion: a point lies 40 mm from frame 0's model, not on "
            "the LV");
  far.anterior = {At(1.0, 0.0, 65.0)};  // 25 mm off: kept.
  EXPECT_TRUE(AnatomicalLayout(model, far).anatomical);
  RvInsertion together;
  together.source = "RV_INSERT";
  together.unlabelled = {At(1.0, 0.0), At(1.05, 0.0)};
  EXPECT_FALSE(AnatomicalLayout(model, together).anatomical);
}

}  // namespace
}  // namespace pfdm
