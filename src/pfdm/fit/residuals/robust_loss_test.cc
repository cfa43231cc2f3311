#include "pfdm/fit/residuals/robust_loss.h"

#include <cmath>
#include <memory>
#include <random>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(RobustLossTest, NamesTheLossesAndRejectsOthers) {
  for (const char* name : {"none", "huber", "cauchy"}) {
    EXPECT_NO_THROW(CheckLossName(name)) << name;
  }
  EXPECT_EQ(MakeLoss("none", 1.0), nullptr);
  const std::unique_ptr<ceres::LossFunction> huber(MakeLoss("huber", 2.0));
  ASSERT_NE(huber, nullptr);
  double rho[3];
  huber->Evaluate(9.0, rho);  // |r| = 3 > 2: 2 a |r| - a^2.
  EXPECT_DOUBLE_EQ(rho[0], 2 * 2.0 * 3.0 - 4.0);
  try {
    MakeLoss("tukey", 1.0);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "unknown --loss 'tukey' (expected none, huber or cauchy)");
  }
}

TEST(RobustLossTest, TuningConstantsAreTheTextbooks) {
  EXPECT_EQ(LossTuning("huber"), 1.345);
  EXPECT_EQ(LossTuning("cauchy"), 2.385);
  EXPECT_EQ(LossTuning("none"), 1.0);
  EXPECT_THROW(LossTuning("tukey"), InputError);
  // Three sigmas, sigma the scale over the tuning.
  EXPECT_DOUBLE_EQ(OutlierBandMm("huber", 2.69), 6.0);
  EXPECT_DOUBLE_EQ(OutlierBandMm("cauchy", 2.385), 3.0);
  EXPECT_EQ(OutlierBandMm("none", 1.0), 0.0);
}

// rho'(|r|^2): huber 1 within the scale and a / |r| beyond; cauchy
// 1 / (1 + |r|^2 / a^2); 1 without a loss.
TEST(RobustLossTest, WeightsAreTheLossesDerivatives) {
  const std::vector<Eigen::Vector3d> residuals = {
      {0.0, 0.0, 0.0}, {0.3, 0.4, 0.0}, {0.0, 3.0, 4.0}};
  EXPECT_EQ(LossWeights("none", 2.0, residuals),
            (std::vector<double>{1.0, 1.0, 1.0}));
  const std::vector<double> huber = LossWeights("huber", 2.0, residuals);
  EXPECT_DOUBLE_EQ(huber[0], 1.0);
  EXPECT_DOUBLE_EQ(huber[1], 1.0);
  EXPECT_DOUBLE_EQ(huber[2], 2.0 / 5.0);
  const std::vector<double> cauchy = LossWeights("cauchy", 2.0, residuals);
  EXPECT_DOUBLE_EQ(cauchy[0], 1.0);
  EXPECT_DOUBLE_EQ(cauchy[1], 1.0 / (1.0 + 0.25 / 4.0));
  EXPECT_DOUBLE_EQ(cauchy[2], 1.0 / (1.0 + 25.0 / 4.0));
}

// |N(0, sigma)| distances give sigma back (10,000 draws: the median's
// standard error is 1.6 %); a quarter of them moved 5-10 mm away raise it
// by under half (the median moves to the 2/3 quantile of the rest: 0.97
// sigma, times 1.4826); noise-free distances give the floor.
TEST(RobustLossTest, ScaleIsSigmaAndOutliersBarelyMoveIt) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.8);
  std::uniform_real_distribution<double> far(5.0, 10.0);
  std::vector<double> distances;
  for (int i = 0; i < 10000; ++i) distances.push_back(std::abs(noise(random)));
  EXPECT_NEAR(RobustScaleMm(distances), 0.8, 0.8 * 0.05);
  for (int i = 0; i < 10000; i += 4) distances[i] = far(random);
  const double with_outliers = RobustScaleMm(distances);
  EXPECT_GT(with_outliers, 0.8);
  EXPECT_NEAR(with_outliers, 1.4826 * 0.97 * 0.8, 0.8 * 0.06);
  EXPECT_EQ(RobustScaleMm({0.0, 0.0, 0.001}), kMinLossScaleMm);
  EXPECT_EQ(RobustScaleMm({}), kMinLossScaleMm);
  EXPECT_DOUBLE_EQ(RobustScaleMm({1.0, 2.0, 3.0, 4.0}), 1.4826 * 2.5);
}

}  // namespace
}  // namespace pfdm
