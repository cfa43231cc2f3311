#include "pfdm/fit/problem/gauge.h"

#include <algorithm>
#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

bool Holds(const std::vector<int>& held, int f) {
  return std::find(held.begin(), held.end(), f) != held.end();
}

TEST(GaugeTest, ReferenceFrameHoldsTwistBendingAndA3) {
  const ModelConfig config = ModelConfig::Paper(9);
  const std::vector<int> knot = HeldEntries(config, FrameKind::kReference, 4);
  for (int f : {kA3, kTau, kB0, kB1, kB2, kB3, kA0, kEps1, kEps2, kE3o}) {
    EXPECT_TRUE(Holds(knot, f)) << FunctionName(f);
  }
  for (int f : {kA1, kA2, kE1o, kE2o}) {
    EXPECT_FALSE(Holds(knot, f)) << FunctionName(f);
  }
  // a0 is a constant of the paper model: the globals block holds the rest.
  const std::vector<int> globals =
      HeldEntries(config, FrameKind::kReference, kGlobalsBlock);
  EXPECT_EQ(static_cast<int>(globals.size()), kNumFunctions);
}

TEST(GaugeTest, LaterFramesFreeTwistOnlyWhenTracked) {
  const ModelConfig config = ModelConfig::Paper(9);
  const std::vector<int> tracked = HeldEntries(config, FrameKind::kTracked, 2);
  const std::vector<int> untracked =
      HeldEntries(config, FrameKind::kUntracked, 2);
  for (int f : {kA1, kA2, kA3, kB0, kB1, kB2, kB3, kE1o, kE2o}) {
    EXPECT_FALSE(Holds(tracked, f)) << FunctionName(f);
    EXPECT_FALSE(Holds(untracked, f)) << FunctionName(f);
  }
  EXPECT_FALSE(Holds(tracked, kTau));
  EXPECT_TRUE(Holds(untracked, kTau));
}

TEST(GaugeTest, SpanAxialExtentReachesTheTopPointKeepingApexAndRadii) {
  Model model = TestSpheroid(9);
  const double apex_before = model.WorldPoint(model.config.u_min, 0.0).z();
  const double radius_before = model.WorldPoint(0.0, 0.0).x();
  const std::vector<Eigen::Vector3d> points = {{0.0, 0.0, apex_before},
                                               {0.0, 0.0, 42.0}};
  SpanAxialExtent(points, FitOptions(), &model);
  EXPECT_NEAR(model.WorldPoint(model.config.u_min, 0.0).z(), apex_before, 1e-9);
  // The rim (u_max) centre reaches the top point.
  const double rim = model.WorldPoint(model.config.u_max, 0.0).z();
  EXPECT_NEAR(rim, 42.0, 1e-9);
  // Radii in mm are kept at the same height fraction of a0 a_i.
  EXPECT_NEAR(model.state.globals[kA0] * model.FunctionAt(kA1, 0.0),
              radius_before, 1e-9);
}

TEST(GaugeTest, TopHeightIsNanWithoutPoints) {
  const Model model = TestSpheroid(9);
  EXPECT_TRUE(std::isnan(TopHeight({}, FitOptions(), model)));
}

}  // namespace
}  // namespace pfdm
