#include "pfdm/report/local_field_noise.h"

#include <cmath>

#include "Eigen/Core"
#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/local_noise.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/number_uncertainty.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

SequenceFit FitLvSequence(int seed, double noise_mm, bool uncertainty,
                          bool local = true) {
  FitOptions options;
  options.uncertainty = uncertainty;
  options.local.enabled = local;
  return FitSequence(LvTwoFrameTags(400, seed, noise_mm), ModelConfig::Paper(9),
                     options);
}

FitAnalysis FitLv(int seed, double noise_mm, bool uncertainty,
                  bool local = true) {
  return AnalyzeFit(FitLvSequence(seed, noise_mm, uncertainty, local));
}

// The bias measured a second way: the noisy fit's GCS minus the same
// tags' noise-free fit's, against the draws' estimate of it.  On 400 tags
// with 0.5 mm of noise the local field's wiggles make GCS 0.6-0.85 points
// less negative (local field off: 0.03); the estimate finds 0.7-0.77, and
// the interval about the value minus it holds the noise-free GCS, where
// the value's own interval (half-width 0.35) never did.
TEST(LocalFieldNoiseTest, TheGcsBiasIsTheNoisesAndTheIntervalHoldsTheTruth) {
  double measured = 0.0, estimated = 0.0;
  for (int seed : {1000, 1001, 1002}) {
    const FitAnalysis noisy = FitLv(seed, 0.5, true);
    const FitAnalysis clean = FitLv(seed, 0.0, false);
    ASSERT_TRUE(noisy.noise_bias.computed);
    const double value = noisy.strain[1].gcs_percent;
    const double bias = noisy.noise_bias.strain[1].gcs_percent;
    const double half = HalfWidth95(noisy.sd.strain[1].gcs_percent);
    const double truth = clean.strain[1].gcs_percent;
    EXPECT_GT(std::abs(value - truth), half) << seed;
    EXPECT_LT(std::abs(value - bias - truth), half) << seed;
    measured += (value - truth) / 3;
    estimated += bias / 3;
  }
  EXPECT_NEAR(estimated, measured, 0.15);
  EXPECT_GT(measured, 0.5);
}

// The draws measured on three threads give one thread's spread and bias
// to the bit (the draws summed in their order), the delta method's sds
// with them (number_uncertainty_test.cc).
TEST(LocalFieldNoiseTest, ThreadsGiveTheSameSpreadAndBiasToTheBit) {
  const SequenceFit fit = FitLvSequence(1000, 0.5, true);
  ASSERT_EQ(fit.threads, 1);
  SequenceFit threaded = fit;
  threaded.threads = 3;
  const FitAnalysis one = AnalyzeFit(fit);
  const FitAnalysis three = AnalyzeFit(threaded);
  ASSERT_TRUE(one.noise_bias.computed && three.noise_bias.computed);
  ASSERT_GE(fit.frames[1].covariance.local_noise.size(), 2u);
  ExpectSameBits(Flatten(one.sd), Flatten(three.sd), "sd");
  ExpectSameBits(Flatten(one.noise_bias), Flatten(three.noise_bias), "bias");
}

// The volume fraction is near linear in the field: its bias is under a
// tenth of its sd, and the field's spread adds little to the delta
// method's (the global fit carries the volumes).
TEST(LocalFieldNoiseTest, ANearLinearNumberHasNoBias) {
  const SequenceFit fit = FitLvSequence(1000, 0.5, true);
  const FitAnalysis a = AnalyzeFit(fit);
  const NumberSd global = PropagateUncertainty(fit, a);
  const double sd = a.sd.ejection_fraction.ratio;
  EXPECT_LT(std::abs(a.noise_bias.ejection_fraction.ratio), 0.1 * sd);
  EXPECT_GE(sd, global.ejection_fraction.ratio);
  EXPECT_LT(sd, 1.1 * global.ejection_fraction.ratio);
}

// Without a local field only frame 0's length is drawn
// (LengthNoiseDraws): the volumes widen and take a bias, the same relative
// one at ED and ES, so the volume fraction barely moves; GCS, which the
// top's rise barely changes (model/raised_top.h: the material rings take
// the radii at their new heights), keeps the delta method's sd within
// 1 % (0.13 %).
TEST(LocalFieldNoiseTest, WithoutALocalFieldOnlyTheLengthIsDrawn) {
  const SequenceFit fit = FitLvSequence(1000, 0.5, true, /*local=*/false);
  const FitAnalysis a = AnalyzeFit(fit);
  ASSERT_TRUE(a.sd.computed);
  ASSERT_TRUE(a.noise_bias.computed);
  const NumberSd global = PropagateUncertainty(fit, a);
  const EjectionFraction& sd = a.sd.ejection_fraction;
  const EjectionFraction& bias = a.noise_bias.ejection_fraction;
  const EjectionFraction& value = a.ejection_fraction;
  EXPECT_GT(sd.edv_ml, 1.2 * global.ejection_fraction.edv_ml);
  EXPECT_GT(bias.edv_ml, 0.0);  // The highest noisy point lies too high.
  EXPECT_NEAR(bias.esv_ml / value.esv_ml, bias.edv_ml / value.edv_ml,
              0.2 * bias.edv_ml / value.edv_ml);
  EXPECT_LT(std::abs(bias.ratio), 0.1 * sd.ratio);
  EXPECT_NEAR(a.sd.strain[1].gcs_percent, global.strain[1].gcs_percent,
              1e-2 * global.strain[1].gcs_percent);
}

// Contours: each frame's base rim is held at its own highest points, so
// frame 1 has length draws of its own, independent of frame 0's.
// Shortening s = 100 (1 - L1 / L0) moves by -(100 - s) per unit of frame
// 1's relative stretch: its variance grows by (100 - s)^2 var(draws), to
// the linearisation's accuracy.
TEST(LocalFieldNoiseTest, AnUntrackedFramesLengthIsDrawnToo) {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = 400;
  options.tags = LvTagLayer::kWall;
  options.sampling = LvSampling::kSaxSlices;
  options.num_long_axis_planes = 3;
  options.seed = 1000;
  FitOptions fit_options;
  fit_options.uncertainty = true;
  const SequenceFit fit = FitSequence(MakeLvPhantom(options).points,
                                      ModelConfig::Paper(9), fit_options);
  ASSERT_FALSE(fit.frames[1].tracked);
  const std::vector<double>& draws = fit.frames[1].covariance.length_noise;
  ASSERT_EQ(draws.size(), static_cast<size_t>(kLengthNoiseDraws));
  const Eigen::Map<const Eigen::VectorXd> f(draws.data(), draws.size());
  const double variance =
      (f.array() - f.mean()).square().sum() / (f.size() - 1.0);
  SequenceFit frame_0_only = fit;
  frame_0_only.frames[1].covariance.length_noise.clear();
  const FitAnalysis with = AnalyzeFit(fit);
  const FitAnalysis without = AnalyzeFit(frame_0_only);
  const double s = with.clinical[1].longitudinal_shortening_percent;
  const double sd_with = with.sd.clinical[1].longitudinal_shortening_percent;
  const double sd_without =
      without.sd.clinical[1].longitudinal_shortening_percent;
  const double added = sd_with * sd_with - sd_without * sd_without;
  const double expected = (100.0 - s) * (100.0 - s) * variance;
  EXPECT_GT(expected, 0.1 * sd_without * sd_without);  // Not negligible.
  EXPECT_NEAR(added, expected, 0.1 * expected);
}

}  // namespace
}  // namespace pfdm
