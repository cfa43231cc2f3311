// Regional defects seen through the wall (issue 32): the LV phantom with a
// hypokinetic mid anteroseptal sector (AHA segment 8), 3,000 tags through
// the whole wall with 0.5 mm of noise, fitted as a solid with
// --local_transmural on (a local field d(u, v, w) = S (q + w q_w + k(w)
// q_k), tags' depths held from frame 0, the default).  The lesion either
// spans the wall or holds only its inner half (subendocardial:
// lesion_outer_w 0).
// Each segment's mid-wall radial contraction, wall thickening and each
// layer's Ecc at ES are compared with the phantom's own truth, measured on
// its material points (lv_truth.h, lv_layer_truth.h), in the lesion, its
// three neighbours and the segment opposite it (where a mirror image
// would show).
//
// Measured (fit against truth at ES; the tolerances below):
// - transmural: the lesion's radial contraction 16.9 % (15.9), its
//   neighbours' and the opposite segment's within 0.4 point; the lesion's
//   thickening 20.4 % (16.9) and endocardial Ecc -11.4 % (-8.2), the mid
//   neighbours' thickening 3.7-6.0 points low, the basal one's 0.6;
// - subendocardial: radial contraction within 0.3 point everywhere, the
//   lesion's thickening 17.9 % (18.6), its neighbours' 2.2-4.5 low, the
//   lesion's endocardial Ecc -13.2 % (-8.2) while its epicardium's reads
//   -7.3 % (-6.3).
// Since 2026-12-07 the field bends between the walls (q_k, a kink at w =
// +-1/3) and q_w's ring means leave its displacement free: before, the
// transmural lesion read 24.6 % thick (worst checked 7.7 points, Ecc 4.1),
// the inner half's 16.8 % (3.1, 3.9), and noise-free a line through the
// inner half's step read its middle third thickening (TheInnerHalfsStepIsRead).
// Over seeds 1-4 the worst checked thickening is now 4.7-7.0 points
// (transmural; 5.6-12.2 before) and 3.7-7.0 (subendocardial; 3.1-5.9), the
// worst endocardial Ecc 1.9-3.2 and 2.5-4.9 (2.3-4.1, 2.4-3.9;
// docs/local_deformations.md).  Without the option the ring's depth ranks
// absorb the sector's motion, and the field moves every layer alike: the
// lesion's thickening is its ring's.  Issue 32's 3.5 points for thickening
// and Ecc in the lesion and its neighbours are not met under noise.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_layer_truth.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/rv_insertion.h"

namespace pfdm {
namespace {

// The phantom's segments (its plain sectors from the body's -x, 0-based):
// mid 2 (the lesion), mid 1 and mid 3 beside it, basal 2 above it, mid 5
// opposite.
constexpr int kLesion = 7;
constexpr int kNeighbours[] = {6, 8, 1};
constexpr int kChecked[] = {7, 6, 8, 1, 10};

// The fit's segments are anchored to the phantom's RV insertion (AHA):
// LvAhaSegmentIndex maps the phantom's sectors to them.

struct Case {
  const char* name;
  double outer_w;  // LvDeformation::lesion_outer_w.
  // Points, the worst over the checked segments at ES.
  double radial, thickening, ecc;
};

// Worst |fit - truth| over the checked segments at ES.
struct Worst {
  double radial = 0.0, thickening = 0.0, ecc = 0.0;
};

struct Fitted {
  LvPhantom phantom;
  FitAnalysis analysis;  // AHA segments.
  std::vector<std::vector<LvSegmentLayers>> layers;
};

Fitted FitLesion(double outer_w, bool hold_tag_depths = true,
                 double noise_mm = 0.5, double stiffness = 0.02) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 3000;
  options.noise_mm = noise_mm;
  options.deformation.lesion = true;
  options.deformation.lesion_outer_w = outer_w;
  Fitted f{MakeLvPhantom(options), {}, {}};
  FitOptions fit_options;
  fit_options.local.transmural = true;
  fit_options.hold_tag_depths = hold_tag_depths;
  fit_options.local.stiffness = stiffness;
  const SequenceFit fit =
      FitSequence(f.phantom.points, ModelConfig::Paper(17), fit_options);
  EXPECT_TRUE(fit.config.Solid()) << fit.wall_reason;
  RvInsertion insertion;
  insertion.source = "phantom";
  insertion.anterior = {f.phantom.rv_anterior};
  insertion.inferior = {f.phantom.rv_inferior};
  f.analysis = AnalyzeFit(fit, {}, AnatomicalLayout(fit.ModelAt(0), insertion));
  EXPECT_TRUE(f.analysis.layout.anatomical);
  f.layers = MeasureLvLayerTruth(f.phantom);
  return f;
}

double LesionThickening(const Fitted& f) {
  return f.analysis.region_motion.back()[LvAhaSegmentIndex(kLesion)]
      .thickening_percent;
}

double EccAt(const Fitted& f, int phantom_index, int layer) {
  return f.analysis.region_layers.back()[LvAhaSegmentIndex(phantom_index)]
      .layers[layer]
      .ecc_percent;
}

Worst CompareAtEs(const Fitted& f) {
  Worst worst;
  const size_t es = f.analysis.region_motion.size() - 1;
  for (int r : kChecked) {
    const RegionMotion& fit =
        f.analysis.region_motion[es][LvAhaSegmentIndex(r)];
    const LvSegmentTruth& truth = f.phantom.truth[es].segments[r];
    std::printf("ES %-20s radial %5.1f (%5.1f) thickening %5.1f (%5.1f)",
                f.analysis.regions[LvAhaSegmentIndex(r)].Name().c_str(),
                fit.radial_contraction_percent,
                truth.radial_contraction_percent, fit.thickening_percent,
                truth.wall_thickening_percent);
    worst.radial =
        std::max(worst.radial, std::abs(fit.radial_contraction_percent -
                                        truth.radial_contraction_percent));
    worst.thickening = std::max(
        worst.thickening,
        std::abs(fit.thickening_percent - truth.wall_thickening_percent));
    for (int k = 0; k < kWallLayers; ++k) {
      const double true_ecc = f.layers[es][r].layers[k].ecc_percent;
      std::printf(" %s Ecc %5.1f (%5.1f)", kLayerNames[k], EccAt(f, r, k),
                  true_ecc);
      worst.ecc = std::max(worst.ecc, std::abs(EccAt(f, r, k) - true_ecc));
    }
    std::printf("\n");
  }
  return worst;
}

class LvTransmuralLesionTest : public testing::TestWithParam<Case> {};

TEST_P(LvTransmuralLesionTest, TheLesionShowsInItsSegmentAndNowhereElse) {
  const Case c = GetParam();
  const Fitted f = FitLesion(c.outer_w);
  const Worst worst = CompareAtEs(f);
  std::printf("%s: worst radial %.2f, thickening %.2f, Ecc %.2f points\n",
              c.name, worst.radial, worst.thickening, worst.ecc);
  EXPECT_LT(worst.radial, c.radial);
  EXPECT_LT(worst.thickening, c.thickening);
  EXPECT_LT(worst.ecc, c.ecc);
  // The lesion's own thickening: within 4 points (transmural, 3.9 off;
  // 7.7 before the kink) and 1.5 (subendocardial, 0.2).
  const double truth =
      f.phantom.truth.back().segments[kLesion].wall_thickening_percent;
  EXPECT_NEAR(LesionThickening(f), truth, c.outer_w > 0.5 ? 4.0 : 1.5);
  // The lesion's endocardium shortens at least 7 points less than each
  // neighbour's (measured 10.4-13.2), and it is the segment's own.
  for (int r : kNeighbours) {
    EXPECT_GT(EccAt(f, kLesion, 0), EccAt(f, r, 0) + 7.0) << r;
  }
}

// With the tags ranked among their neighbours in every frame (the option's
// behaviour until 2026-12-07, `--tag_depths ranked`), the transmural
// lesion's thickening and endocardial Ecc read further toward its
// neighbours' (23.1 % and -12.6 % against 20.8 and -11.5 held; truth 16.9
// and -8.2; over seeds 1-4 ranked 23.1-31.5 %, held 17.3-24.0).
TEST(LvTransmuralLesionRankedTest, RanksReadTheLesionCloserToItsRing) {
  const Fitted held = FitLesion(1.0);
  const Fitted ranked = FitLesion(1.0, /*hold_tag_depths=*/false);
  EXPECT_GT(LesionThickening(ranked), LesionThickening(held) + 1.5);
  EXPECT_LT(EccAt(ranked, kLesion, 0), EccAt(held, kLesion, 0) - 0.5);
}

// Noise-free, at stiffness 0.005: the inner-half lesion's contraction
// steps from 30 % of normal to normal about w = 0, which a line through
// the wall reads 1.5 times: the lesion's middle third thickened by 8.5 %
// where it thins by 24.6, the lesion read 14.8 % thick (18.6) and the
// worst checked segment 4.8 points off.  With the kink: the middle third
// -25.9 %, the lesion 16.1 % (q_w's ring means hold the global
// thickness's share of the line's error), the worst checked 2.5 points,
// its radial contraction within 0.2.  The endocardium's Ecc still reads
// 3.7 points too contracted (-11.9 % against -8.2).
TEST(LvTransmuralLesionNoiseFreeTest, TheInnerHalfsStepIsRead) {
  const Fitted f = FitLesion(0.0, /*hold_tag_depths=*/true, /*noise_mm=*/0.0,
                             /*stiffness=*/0.005);
  const Worst worst = CompareAtEs(f);
  EXPECT_LT(worst.thickening, 3.5);
  EXPECT_LT(worst.radial, 0.5);
  const size_t es = f.analysis.region_motion.size() - 1;
  const double truth =
      f.phantom.truth[es].segments[kLesion].wall_thickening_percent;
  EXPECT_NEAR(LesionThickening(f), truth, 3.0);
  const LayerStrain& middle =
      f.analysis.region_layers[es][LvAhaSegmentIndex(kLesion)].layers[1];
  const double middle_truth =
      f.layers[es][kLesion].layers[1].thickening_percent;
  EXPECT_NEAR(middle.thickening_percent, middle_truth, 5.0);
  EXPECT_LT(middle.thickening_percent, -15.0);
}

INSTANTIATE_TEST_SUITE_P(Lesions, LvTransmuralLesionTest,
                         testing::Values(Case{"transmural", 1.0, 1.5, 6.5, 4.5},
                                         Case{"subendocardial", 0.0, 0.5, 5.0,
                                              5.5}));

}  // namespace
}  // namespace pfdm
