// The temporal prior (fit/stages/temporal_prior.h, --temporal_prior) on
// contours the model did not generate: the independent LV phantom's full
// cycle (p = sin^2(pi s)) seen as untracked mid-wall contours on 9 fixed
// short-axis planes, fitted without and with the default pull toward the
// previous frame (0.05), against the phantom's measured truth.  At a
// cine's 25 frames end-systole (frame 12) reads radial contraction 21.33
// -> 21.24 % (truth 21.90), longitudinal shortening 13.87 -> 13.69 %
// (17.00: short-axis slices see the length only at the apex), GCS -19.01
// -> -18.94 %; the pull lags where the cycle moves fastest (frame 9: LS
// 13.28 -> 9.56 %, truth 14.51), and the largest level strain spike goes
// 4.94 -> 4.08 points.  At 9 frames a cycle the pull lagged end-systole
// by 1.4 points of LS, and such a sequence is fitted without it.
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

LvPhantom ContourCycle(int num_frames, int long_axis_planes = 0) {
  LvPhantomOptions options;
  options.num_long_axis_planes = long_axis_planes;
  options.kinematics = LvKinematics::kCycle;
  options.sampling = LvSampling::kSaxSlices;
  options.num_tags = 1500;
  options.num_frames = num_frames;
  return MakeLvPhantom(options);
}

FitAnalysis FitCycle(const LvPhantom& phantom, double temporal_prior) {
  FitOptions options;
  options.temporal_prior_weight = temporal_prior;
  return AnalyzeFit(
      FitSequence(phantom.points, ModelConfig::Paper(17), options));
}

// A cine's 25 frames a cycle, where the pull applies
// (kTemporalPriorMinFrames).
TEST(LvTemporalPriorTest, ContourCycleKeepsItsEndSystole) {
  const LvPhantom phantom = ContourCycle(25);
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
  int es = 0;
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    if (phantom.truth[t].mean_radial_contraction_percent >
        phantom.truth[es].mean_radial_contraction_percent) {
      es = static_cast<int>(t);
    }
  }
  const int last = static_cast<int>(phantom.truth.size()) - 1;
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
  // The cycle closes: the last frame is ED again.
  EXPECT_NEAR(fit.clinical[last].volume_ml / fit.clinical[0].volume_ml, 1.0,
              0.03);
  EXPECT_NEAR(fit.clinical[last].radial_contraction_percent, 0.0, 1.5);
  // The pull adds no spike.  The largest, with it or without (-5.58 and
  // -5.53 points), is at frame 15, next to where the basal slice comes
  // back into the data (the shortening steps from 15 % to 3 % at frame 16,
  // the truth's from 14.5 to 12.8), a step in the data the pull does not
  // smooth away.
  std::printf("largest spike at frame %d (%s)\n", spike.frame,
              spike.longitudinal ? "Ell" : "Ecc");
  EXPECT_LE(std::abs(spike.points), std::abs(before.points) + 0.1);
}

// 9 frames a cycle move three times as far a frame as a cine's 25, and
// the pull lagged end-systole (temporal_prior.h): such a sequence is
// fitted without it, whatever the weight.
TEST(LvTemporalPriorTest, ShortCycleIsNotPulled) {
  const LvPhantom phantom = ContourCycle(9);
  const FitAnalysis none = FitCycle(phantom, 0.0);
  const FitAnalysis fit = FitCycle(phantom, kSuggestedTemporalPriorWeight);
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    EXPECT_EQ(fit.clinical[t].volume_ml, none.clinical[t].volume_ml) << t;
    EXPECT_EQ(fit.clinical[t].longitudinal_shortening_percent,
              none.clinical[t].longitudinal_shortening_percent)
        << t;
  }
}

// Issue 31's contour phantom: the cycle's 25 frames as a cine sees them,
// 9 short-axis and 3 long-axis planes (biv-me's views) through the
// independent LV, untracked contours, the default fit.  Every frame
// settles in 2-3 rounds; longitudinal shortening within 1.5 points of the
// truth (16.32 % at end-systole against 17.00: the long-axis contours see
// the base descend, and the pull toward frame 0 leaves the length to them;
// holding it too, 14.59), volumes within 1 %, the largest strain spike
// 1.2 points.  Radial contraction within 0.6 points (21.65 % at
// end-systole against 21.90): the pull toward frame 0's radii is 0.3 of
// the rest where the slices cover a ring (FitOptions::
// untracked_prior_covered_radii_scale); at full strength it read 20.27,
// up to 2.0 points under in systole.
TEST(LvTemporalPriorTest, ShortAndLongAxisContoursFollowTheCycle) {
  const LvPhantom phantom = ContourCycle(25, 3);
  const SequenceFit sequence =
      FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
  const FitAnalysis fit = AnalyzeFit(sequence);
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    const LvFrameTruth& truth = phantom.truth[t];
    const ClinicalSummary& c = fit.clinical[t];
    std::printf(
        "frame %2zu  rounds %2d  unsettled %.2f  volume %.1f (truth %.1f) ml  "
        "LS %.2f (%.2f) %%  RC %.2f (%.2f) %%\n",
        t, sequence.frames[t].correspondence_rounds,
        sequence.frames[t].unsettled_mm, c.volume_ml, truth.volume_ml,
        c.longitudinal_shortening_percent,
        truth.longitudinal_shortening_percent, c.radial_contraction_percent,
        truth.mean_radial_contraction_percent);
    EXPECT_EQ(sequence.frames[t].unsettled_mm, 0.0) << t;
    EXPECT_NEAR(c.radial_contraction_percent,
                truth.mean_radial_contraction_percent, 1.0)
        << t;
    EXPECT_NEAR(c.longitudinal_shortening_percent,
                truth.longitudinal_shortening_percent, 2.0)
        << t;
    EXPECT_NEAR(c.volume_ml / truth.volume_ml, 1.0, 0.02) << t;
  }
  const StrainSpike spike = LargestStrainSpike(fit.strain);
  std::printf("largest spike %.2f points (frame %d)\n", spike.points,
              spike.frame);
  EXPECT_LT(std::abs(spike.points), 3.0);
}

}  // namespace
}  // namespace pfdm
