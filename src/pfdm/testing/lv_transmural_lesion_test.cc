// Regional defects seen through the wall (issue 32): the LV phantom with a
// hypokinetic mid anteroseptal sector (AHA segment 8), 3,000 tags through
// the whole wall with 0.5 mm of noise, fitted as a solid with
// --local_transmural on (a local field d(u, v, w) = S (q + w q_w), tags'
// depths held from frame 0, the default).  The lesion either spans the
// wall or holds only its inner half (subendocardial: lesion_outer_w 0).
// Each segment's mid-wall radial contraction, wall thickening and each
// layer's Ecc at ES are compared with the phantom's own truth, measured on
// its material points (lv_truth.h, lv_layer_truth.h), in the lesion, its
// three neighbours and the segment opposite it (where a mirror image
// would show).
//
// Measured (fit against truth at ES; the tolerances below):
// - transmural: the lesion's radial contraction 16.9 % (15.9), its
//   neighbours' and the opposite segment's within 0.5 point; the lesion's
//   thickening 24.6 % (16.9) and endocardial Ecc -12.4 % (-8.2), the
//   mid neighbours' thickening 3.2-4.4 points low, the basal one's 1.6 high;
// - subendocardial: radial contraction within 0.4 point everywhere,
//   thickening within 3.1 (the lesion's 16.8 % against 18.6), the
//   lesion's endocardial Ecc -12.2 % (-8.2) while its epicardium's reads
//   -8.3 % (-6.3).
// Until 2026-12-07 the option ranked the tags among their neighbours in
// every frame (now `--tag_depths ranked` with it): the transmural lesion's
// thickening read 28.1 % and its endocardial Ecc -14.0 %, the worst
// checked segment's thickening 11.1 points off and Ecc 5.7; over seeds 1-4
// the worst thickening 11.1-17.1 points (transmural) and 3.3-8.8
// (subendocardial), the worst endocardial Ecc 4.7-8.5, against 5.6-12.2,
// 3.1-5.9 and 2.3-4.1 held (docs/local_deformations.md).  Without the
// option the ring's depth ranks absorb the sector's motion, and the field
// moves every layer alike: the lesion's thickening is its ring's.
// Issue 32's 3.5 points for thickening and Ecc in the lesion are not met.
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

Fitted FitLesion(double outer_w, bool hold_tag_depths = true) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 3000;
  options.noise_mm = 0.5;
  options.deformation.lesion = true;
  options.deformation.lesion_outer_w = outer_w;
  Fitted f{MakeLvPhantom(options), {}, {}};
  FitOptions fit_options;
  fit_options.local.transmural = true;
  fit_options.hold_tag_depths = hold_tag_depths;
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
  // The lesion's endocardium shortens at least 7 points less than each
  // neighbour's (measured 11.6-12.8), and it is the segment's own.
  for (int r : kNeighbours) {
    EXPECT_GT(EccAt(f, kLesion, 0), EccAt(f, r, 0) + 7.0) << r;
  }
}

// With the tags ranked among their neighbours in every frame (the option's
// behaviour until 2026-12-07, `--tag_depths ranked`), the transmural
// lesion's thickening and endocardial Ecc read further toward its
// neighbours' (28.1 % and -14.0 % against 24.6 and -12.4 held; truth 16.9
// and -8.2).
TEST(LvTransmuralLesionRankedTest, RanksReadTheLesionCloserToItsRing) {
  const Fitted held = FitLesion(1.0);
  const Fitted ranked = FitLesion(1.0, /*hold_tag_depths=*/false);
  const size_t es = held.analysis.region_motion.size() - 1;
  auto thickening = [es](const Fitted& f) {
    return f.analysis.region_motion[es][LvAhaSegmentIndex(kLesion)]
        .thickening_percent;
  };
  EXPECT_GT(thickening(ranked), thickening(held) + 2.0);
  EXPECT_LT(EccAt(ranked, kLesion, 0), EccAt(held, kLesion, 0) - 1.0);
}

INSTANTIATE_TEST_SUITE_P(Lesions, LvTransmuralLesionTest,
                         testing::Values(Case{"transmural", 1.0, 1.5, 8.5, 5.0},
                                         Case{"subendocardial", 0.0, 1.0, 4.0,
                                              4.5}));

}  // namespace
}  // namespace pfdm
