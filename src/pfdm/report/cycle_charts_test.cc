#include "pfdm/report/cycle_charts.h"

#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/report_text.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/testing/truth_as_fit.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// V(t) = 100 + 30 cos(2 pi t / T), T = 0.8 s, sampled every 20 ms: dV/dt =
// -30 (2 pi / T) sin(2 pi t / T), peak 235.6 ml/s, which central
// differences reach sin(w h) / (w h) = 0.996 of: 234.65 ml/s.
TEST(CycleChartsTest, VolumeRateOfAKnownCurve) {
  const double period = 0.8, h = 0.02, w = 2 * kPi / period;
  std::vector<double> volume, seconds;
  for (int t = 0; t <= 40; ++t) {
    seconds.push_back(t * h);
    volume.push_back(100 + 30 * std::cos(w * t * h));
  }
  const std::vector<double> rate = VolumeRate(volume, seconds);
  ASSERT_EQ(rate.size(), 41u);
  const double shrink = std::sin(w * h) / (w * h);
  for (int t = 1; t < 40; ++t) {
    EXPECT_NEAR(rate[t], -30 * w * std::sin(w * t * h) * shrink, 1e-9) << t;
  }
  // One-sided at the ends: (V1 - V0) / h.
  EXPECT_NEAR(rate[0], (volume[1] - volume[0]) / h, 1e-12);
  // ES at T / 2 (frame 20): ejection peaks at T / 4, filling at 3 T / 4.
  const VolumeRatePeaks peaks = PeakVolumeRates(rate, 20);
  EXPECT_NEAR(peaks.ejection, 30 * w * shrink, 1e-9);
  EXPECT_NEAR(peaks.filling, 30 * w * shrink, 1e-9);
  EXPECT_NEAR(peaks.ejection, 234.65, 0.01);
  EXPECT_TRUE(VolumeRate({100.0}, {0.0}).empty());
}

// With the frames' times: against them, the rates in ml/s; without, per
// frame and no rate in ml/s.
TEST(CycleChartsTest, ChartsAgainstTimeWhereKnown) {
  PhantomOptions options;
  options.num_points = 20;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  const std::string untimed = CycleChartsHtml(AnalyzeFit(fit));
  EXPECT_NE(untimed.find("ml/frame"), std::string::npos);
  EXPECT_EQ(untimed.find("Peak ejection rate"), std::string::npos);
  EXPECT_EQ(CountOf(untimed, "class='chart'"), 7);
  // Tags on a mid-wall: no ejection fraction; the cavity's has one.
  EXPECT_NE(untimed.find(">midwall volume (not the cavity)<"),
            std::string::npos);
  SequenceFit cavity = fit;
  cavity.surface = WallLayer::kEndocardium;
  const FitAnalysis cavity_analysis = AnalyzeFit(cavity);
  char ef[64];
  std::snprintf(ef, sizeof(ef), ">cavity volume, EF %.1f %%<",
                100.0 * cavity_analysis.ejection_fraction.ratio);
  EXPECT_NE(CycleChartsHtml(cavity_analysis).find(ef), std::string::npos) << ef;
  // Rotation not measured in any frame (contours): no rotation or torsion
  // chart; in some, gaps.
  for (FrameFit& frame : fit.frames) frame.tracked = false;
  const std::string contours = CycleChartsHtml(AnalyzeFit(fit));
  EXPECT_EQ(contours.find("rotation about the LV axis"), std::string::npos);
  EXPECT_EQ(contours.find(">torsion<"), std::string::npos);
  EXPECT_EQ(CountOf(contours, "class='chart'"), 5);
  EXPECT_NE(contours.find(">contraction<"), std::string::npos);
  fit.frames = TruthAsFit(phantom).frames;
  fit.time_ms = {0, 50, 100, 150, 200};
  const std::string timed = CycleChartsHtml(AnalyzeFit(fit));
  EXPECT_NE(timed.find("time from the trigger (ms) 150: "), std::string::npos);
  EXPECT_NE(timed.find("Peak ejection rate <b>"), std::string::npos);
  EXPECT_NE(timed.find("torsion, time from the trigger (ms) 200: "),
            std::string::npos);
  EXPECT_EQ(timed.find("nan"), std::string::npos);
}

// With --uncertainty on, each bar is centred on the value minus its noise
// bias, as fit.json's ci95 is: frame 1's volume V with sd 1 and bias 2 has
// the bar V - 2 -+ 1.96.
TEST(CycleChartsTest, BarsAreCentredOnTheValueLessItsBias) {
  PhantomOptions options;
  options.num_points = 20;
  FitAnalysis analysis = AnalyzeFit(TruthAsFit(MakePhantom(options)));
  analysis.sd.computed = analysis.noise_bias.computed = true;
  analysis.sd.clinical = analysis.noise_bias.clinical = analysis.clinical;
  analysis.sd.strain = analysis.noise_bias.strain = analysis.strain;
  for (size_t t = 0; t < analysis.clinical.size(); ++t) {
    analysis.sd.clinical[t].volume_ml = 1.0;
    analysis.noise_bias.clinical[t].volume_ml = 2.0;
    analysis.sd.strain[t].gcs_percent = 0.5;
    analysis.noise_bias.strain[t].gcs_percent = 0.0;
  }
  const double v = analysis.clinical[1].volume_ml;
  const std::string html = CycleChartsHtml(analysis);
  const std::string volume = "volume (ml), frame 1: " + Fixed(v, 2) +
                             ", 95 %: " + Fixed(v - 2.0 - 1.96, 2) + " to " +
                             Fixed(v - 2.0 + 1.96, 2);
  EXPECT_NE(html.find(volume), std::string::npos) << volume;
  // No bias: +- about the value.
  EXPECT_NE(html.find("GCS (global), frame 1: " +
                      Fixed(analysis.strain[1].gcs_percent, 2) +
                      " &#177; 0.98 (95 %)"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
