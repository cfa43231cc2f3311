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
  EXPECT_NEAR(AxialLength(model), 42.0 - apex_before, 1e-9);
  // Radii in mm are kept at the same height fraction of a0 a_i.
  EXPECT_NEAR(model.state.globals[kA0] * model.FunctionAt(kA1, 0.0),
              radius_before, 1e-9);
}

// The rim already raised to 25 mm by two outliers on the surface's
// continuation (at 22.5 and 24.5 mm), over data that end at 20 mm: without
// a loss the highest point is the top; with one, a top needs two points
// within three sigmas below it (cauchy at 0.5 mm: sigma 0.21 mm), which
// only the data's end has.
TEST(GaugeTest, WithALossTheTopNeedsPointsBelowIt) {
  Model model = TestSpheroid(9);
  const double apex = model.WorldPoint(model.config.u_min, 0.0).z();
  SpanAxialExtent({{0.0, 0.0, apex}, {0.0, 0.0, 25.0}}, FitOptions(), &model);
  // u of the model's point at height z, by bisection (z rises with u).
  auto u_at = [&](double z) {
    double low = model.config.u_min, high = model.config.u_max;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (low + high);
      (model.WorldPoint(mid, 0.0).z() < z ? low : high) = mid;
    }
    return low;
  };
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 100; ++i) {
    const double u = u_at(10.0 + 0.1 * i);
    points.push_back(model.WorldPoint(u, 0.37 * i));
  }
  points.push_back(model.WorldPoint(u_at(20.0), 1.0));
  for (double z : {22.5, 24.5})
    points.push_back(model.WorldPoint(u_at(z), 2.0));
  const double center = model.state.center[2];  // Heights are from it.
  FitOptions options;
  EXPECT_NEAR(TopHeight(points, options, model), 24.5 - center, 1e-6);
  options.loss = "cauchy";
  options.loss_scale_mm = 0.5;
  EXPECT_NEAR(TopHeight(points, options, model), 20.0 - center, 1e-6);
  // Points 0.1 mm apart have no two within 0.063 mm: without support
  // anywhere, the highest point.
  options.loss_scale_mm = 0.05;
  EXPECT_NEAR(TopHeight(points, options, model), 24.5 - center, 1e-6);
}

TEST(GaugeTest, TopHeightIsNanWithoutPoints) {
  const Model model = TestSpheroid(9);
  EXPECT_TRUE(std::isnan(TopHeight({}, FitOptions(), model)));
}

}  // namespace
}  // namespace pfdm
