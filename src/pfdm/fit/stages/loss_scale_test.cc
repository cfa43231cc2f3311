#include "pfdm/fit/stages/loss_scale.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

TEST(LossScaleTest, AutoMeasuresOnlyWithALoss) {
  FitOptions options;
  EXPECT_TRUE(options.loss_scale_auto);
  EXPECT_FALSE(MeasuresLossScale(options));  // No loss.
  options.loss = "huber";
  EXPECT_TRUE(MeasuresLossScale(options));
  EXPECT_EQ(WithoutLoss(options).loss, "none");
  EXPECT_EQ(WithLossScale(options, 0.7).loss_scale_mm, 0.7);
  EXPECT_EQ(WithLossScale(options, 0.7).loss, "huber");
  options.loss_scale_auto = false;
  options.loss_scale_mm = 2.0;
  EXPECT_FALSE(MeasuresLossScale(options));
  EXPECT_EQ(WithLossScale(options, 0.7).loss_scale_mm, 2.0);
  EXPECT_DOUBLE_EQ(RankBandMm("huber", 1.345), 3.0);
  EXPECT_DOUBLE_EQ(RankBandMm("cauchy", 2.385), 3.0);
}

// Points off the spheroid along its normal by +-0.6 mm, three of them 8 mm:
// sigma is 1.4826 x 0.6 whatever the three do, and each loss takes its
// multiple of it.
TEST(LossScaleTest, MeasuresTheMedianDistance) {
  const Model model = TestSpheroid(5);
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  for (int i = 0; i < 20; ++i) {
    const MaterialPoint m{-1.0 + 0.08 * i, 0.3 * i, 0.0};
    const Eigen::Vector3d normal = SurfaceNormal(model, m.u, m.v);
    const double off = i < 3 ? 8.0 : (i % 2 == 0 ? 0.6 : -0.6);
    material.push_back(m);
    points.push_back(model.WorldPoint(m.u, m.v) + off * normal);
  }
  EXPECT_NEAR(MeasureLossScale("huber", model, points, material),
              1.345 * 1.4826 * 0.6, 1e-9);
  EXPECT_NEAR(MeasureLossScale("cauchy", model, points, material),
              2.385 * 1.4826 * 0.6, 1e-9);
}

// Each frame's weights at its residuals and its own scale; none without a
// loss.
TEST(LossScaleTest, WeighsEveryFramesPoints) {
  SequenceFit fit;
  fit.frames.resize(2);
  fit.frames[0].loss_scale_mm = 1.0;
  fit.frames[1].loss_scale_mm = 2.0;
  for (FrameFit& frame : fit.frames) {
    frame.residuals = {{0.5, 0.0, 0.0}, {0.0, 4.0, 0.0}};
  }
  WeighPoints("none", &fit);
  EXPECT_TRUE(fit.frames[0].loss_weights.empty());
  WeighPoints("huber", &fit);
  EXPECT_EQ(fit.frames[0].loss_weights, (std::vector<double>{1.0, 0.25}));
  EXPECT_EQ(fit.frames[1].loss_weights, (std::vector<double>{1.0, 0.5}));
}

}  // namespace
}  // namespace pfdm
