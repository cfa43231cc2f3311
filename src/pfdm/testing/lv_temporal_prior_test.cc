// The temporal prior (fit/stages/temporal_prior.h, --temporal_prior) on
// contours the model did not generate: the independent LV phantom's full
// cycle (9 frames, p = sin^2(pi s): end-systole at frame 4, back to ED at
// frame 8) seen as untracked mid-wall contours on 9 fixed short-axis
// planes, fitted without and with the suggested pull toward the previous
// frame (0.05), against the phantom's measured truth.  The pull lags a
// motion this coarsely sampled (a third of the cycle's shortening between
// frames 2 and 3; a 25-frame cine moves a third as far a frame):
// end-systole reads radial contraction 21.20 -> 20.40 % (truth 21.90),
// longitudinal shortening 13.78 -> 12.39 % (17.00: short-axis slices see
// the length only at the apex), GCS -18.92 -> -18.19 %, volume 78.0 ->
// 80.1 ml; mid-stroke (frame 3) LS 13.29 -> 9.42 % (14.51), RC 18.48 ->
// 16.78 % (18.69).  The largest level strain spike 5.35 -> 4.97 points.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/strain_spike.h"

namespace pfdm {
namespace {

LvPhantom ContourCycle() {
  LvPhantomOptions options;
  options.kinematics = LvKinematics::kCycle;
  options.sampling = LvSampling::kSaxSlices;
  options.num_tags = 1500;
  return MakeLvPhantom(options);
}

FitAnalysis FitCycle(const LvPhantom& phantom, double temporal_prior) {
  FitOptions options;
  options.temporal_prior_weight = temporal_prior;
  return AnalyzeFit(
      FitSequence(phantom.points, ModelConfig::Paper(17), options));
}

TEST(LvTemporalPriorTest, ContourCycleKeepsItsEndSystole) {
  const LvPhantom phantom = ContourCycle();
  const FitAnalysis none = FitCycle(phantom, 0.0);
  const FitAnalysis fit = FitCycle(phantom, kSuggestedTemporalPriorWeight);
  ASSERT_EQ(fit.clinical.size(), phantom.truth.size());
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    const LvFrameTruth& truth = phantom.truth[t];
    const ClinicalSummary& a = none.clinical[t];
    const ClinicalSummary& b = fit.clinical[t];
    std::printf(
        "frame %zu  volume %.1f -> %.1f ml  LS %.2f -> %.2f (truth %.2f) %%  "
        "RC %.2f -> %.2f (%.2f) %%  GCS %.2f -> %.2f\n",
        t, a.volume_ml, b.volume_ml, a.longitudinal_shortening_percent,
        b.longitudinal_shortening_percent,
        truth.longitudinal_shortening_percent, a.radial_contraction_percent,
        b.radial_contraction_percent, truth.mean_radial_contraction_percent,
        none.strain[t].gcs_percent, fit.strain[t].gcs_percent);
  }
  const StrainSpike before = LargestStrainSpike(none.strain);
  const StrainSpike spike = LargestStrainSpike(fit.strain);
  std::printf("largest spike %.2f -> %.2f points\n", before.points,
              spike.points);
  const int es = 4;
  const LvFrameTruth& truth = phantom.truth[es];
  const ClinicalSummary& a = none.clinical[es];
  const ClinicalSummary& b = fit.clinical[es];
  // What the pull may change at end-systole: under 1 point of radial
  // contraction and GCS, 2 of longitudinal shortening, 3 % of the volume.
  EXPECT_NEAR(b.radial_contraction_percent, a.radial_contraction_percent, 1.0);
  EXPECT_NEAR(fit.strain[es].gcs_percent, none.strain[es].gcs_percent, 1.0);
  EXPECT_NEAR(b.longitudinal_shortening_percent,
              a.longitudinal_shortening_percent, 2.0);
  EXPECT_NEAR(b.volume_ml / a.volume_ml, 1.0, 0.03);
  // Against the truth.  (The volumes are not the truth's: the fit ends at
  // the highest slice, 90 % up, the truth's mid-wall at the base.)
  EXPECT_NEAR(b.radial_contraction_percent,
              truth.mean_radial_contraction_percent, 2.0);
  EXPECT_NEAR(b.longitudinal_shortening_percent,
              truth.longitudinal_shortening_percent, 5.5);
  // The cycle closes: frame 8 is ED again (143.9 against 145.6 ml).
  EXPECT_NEAR(fit.clinical[8].volume_ml / fit.clinical[0].volume_ml, 1.0, 0.03);
  EXPECT_NEAR(fit.clinical[8].radial_contraction_percent, 0.0, 1.5);
  EXPECT_LE(std::abs(spike.points), std::abs(before.points));
}

}  // namespace
}  // namespace pfdm
