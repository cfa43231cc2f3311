#include "pfdm/model/knot_resampling.h"

#include <algorithm>
#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Five knots of uneven values in every free function, a pose of its own.
Model FiveKnotModel() {
  const ModelConfig config = ModelConfig::Paper(5);
  Model model = Model::Uniform(config, DefaultFunctionValues());
  for (int k = 0; k < 5; ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      model.state.knots[k][f] = 1.0 + 0.1 * f + 0.3 * std::sin(1.7 * k + f);
    }
  }
  model.state.center = {1.0, -2.0, 3.0};
  model.state.quaternion = {0.5, 0.5, -0.5, 0.5};
  model.state.globals[kA0] = 42.0;
  return model;
}

// 5 knots are among 17's: the functions agree at every u, knots or not.
TEST(KnotResamplingTest, NestedKnotsKeepEveryFunctionEverywhere) {
  const Model coarse = FiveKnotModel();
  const Model fine = ResampleKnots(coarse, ModelConfig::Paper(17));
  ASSERT_EQ(fine.state.knots.size(), 17u);
  EXPECT_EQ(fine.config.num_knots, 17);
  EXPECT_EQ(fine.state.center, coarse.state.center);
  EXPECT_EQ(fine.state.quaternion, coarse.state.quaternion);
  EXPECT_EQ(fine.state.globals[kA0], 42.0);
  for (int i = 0; i <= 200; ++i) {
    const double u = coarse.config.u_min +
                     (coarse.config.u_max - coarse.config.u_min) * i / 200;
    const FunctionValues a = coarse.FunctionsAt(u);
    const FunctionValues b = fine.FunctionsAt(u);
    for (int f = 0; f < kNumFunctions; ++f) {
      EXPECT_NEAR(b[f], a[f], 1e-12) << FunctionName(f) << " at u " << u;
    }
  }
}

// 10 knots are not: the functions agree at 10's knots and differ between.
TEST(KnotResamplingTest, OtherKnotsSampleTheFunctionsAtTheirKnots) {
  const Model coarse = FiveKnotModel();
  const ModelConfig config = ModelConfig::Paper(10);
  const Model resampled = ResampleKnots(coarse, config);
  double between = 0.0;
  for (int k = 0; k < 10; ++k) {
    const double u = config.Grid().KnotU(k);
    const FunctionValues a = coarse.FunctionsAt(u);
    EXPECT_NEAR(resampled.FunctionsAt(u)[kA1], a[kA1], 1e-12) << "knot " << k;
    if (k + 1 < 10) {
      const double mid = 0.5 * (u + config.Grid().KnotU(k + 1));
      between = std::max(between, std::abs(resampled.FunctionsAt(mid)[kTau] -
                                           coarse.FunctionsAt(mid)[kTau]));
    }
  }
  EXPECT_GT(between, 1e-4);
}

}  // namespace
}  // namespace pfdm
