// The solid (model/transmural.h) fitted to tags through the wall of a
// mid-ventricular segment, no apex (issue 32): the cylinder and the prolate
// shell's segment (lv_phantom.h), each wall under both thickening laws
// (lv_motion.h), with and without noise.  The clinical ring means are taken
// where frame 0 has data (ClinicalRingSpan), the truth's over the segment's
// heights; thickening and each wall's radial contraction are checked at
// every frame.
//
// Issue 32's targets: thickening within 3 points at every frame, each
// wall's radial contraction within 2, over noise draws from about 3,000
// tags (LvWallSegmentSeedsTest below), the tags' depths held from frame 0
// (the default).  At 1,500 tags one draw in a few misses: seed 1's noisy
// prolate segment under the incompressible law read 20.9 against 17.1 at
// frame 1 held (ranked 2.7 points over).  Measured at 1,500 tags (docs/
// gauge.md "The profile across the wall"), ranked, with the squeeze (a
// cubic depth) and its noise taken out: thickening 2.4 points off at worst
// (prolate, designed law, noise-free, ES: 41.7 against 44.1), endocardium
// 1.8 (prolate, incompressible: 27.0 against 28.8), epicardium 0.9.
// Before, with a quadratic depth, thickening read up to 3.9 points under
// and the endocardium 2.2.
//
// The myocardium between the data's first and last material rings
// (material_myocardium.h): on the cylinder within 5 points of the truth's
// change (at worst +6.2 % against +2.0, designed law, noise-free: the
// wall's top edge thickens 4-9 points too much), and under the
// incompressible law within 5 % of ED on both geometries (at worst +2.2 %).
constexpr double kThickeningPoints = 3.0;
constexpr double kEndoPoints = 2.0;
constexpr double kEpiPoints = 2.0;
constexpr double kMyocardiumPercent = 5.0;
constexpr int kTags = 3000;
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {
namespace {

// Over the segment's heights (truth rings, linear between them).
double SegmentMean(const std::vector<double>& values) {
  const LvHeights band = LvRegionHeights(LvRegion::kMidventricular);
  constexpr int kSamples = 42;
  double sum = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    sum += LvRingValueAt(
        values, band.low + (band.high - band.low) * (k + 0.5) / kSamples);
  }
  return sum / kSamples;
}

// The truth's segment means a frame's fit is held to.
struct WallTruth {
  double thickening, endo, epi;
};
WallTruth SegmentTruth(const LvFrameTruth& truth) {
  return {SegmentMean(truth.wall_thickening_percent),
          SegmentMean(truth.endo.radial_contraction_percent),
          SegmentMean(truth.epi.radial_contraction_percent)};
}

struct Case {
  LvGeometry geometry;
  LvThickeningLaw law;
  double noise_mm;
};

// The segment's tags through the wall over 3 frames.
LvPhantom SegmentPhantom(const Case& c, unsigned seed = 1) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.region = LvRegion::kMidventricular;
  options.geometry = c.geometry;
  options.law = c.law;
  options.noise_mm = c.noise_mm;
  options.num_frames = 3;
  options.num_tags = kTags;
  options.seed = seed;
  if (c.geometry == LvGeometry::kCylinder) {
    options.deformation = CylinderDeformation();
  }
  return MakeLvPhantom(options);
}

class LvWallSegmentTest : public testing::TestWithParam<Case> {};

TEST_P(LvWallSegmentTest, ThickeningAndBothWallsWhereTheDataAre) {
  const Case c = GetParam();
  const LvPhantom phantom = SegmentPhantom(c);
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
  ASSERT_TRUE(fit.config.Solid()) << fit.wall_reason;
  ASSERT_FALSE(fit.apex_in_data);
  const FitAnalysis analysis = AnalyzeFit(fit);
  // The data span the model's upper two thirds at most: no ring below them.
  EXPECT_GT(analysis.ring_span.low, 0.2);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const ClinicalSummary& s = analysis.clinical[t];
    const LvFrameTruth& truth = phantom.truth[t];
    const auto [thickening, endo, epi] = SegmentTruth(truth);
    const double myocardium_change =
        100.0 *
        (truth.myocardial_volume_ml / phantom.truth[0].myocardial_volume_ml -
         1.0);
    std::printf(
        "%s %s noise %.1f frame %zu: thickening %.1f (%.1f) endo %.1f (%.1f) "
        "epi %.1f (%.1f) myocardium %.1f ml, material %.1f ml %+.2f %% "
        "(%+.2f)\n",
        LvGeometryName(c.geometry).c_str(), LvThickeningLawName(c.law).c_str(),
        c.noise_mm, t, s.wall_thickening_percent, thickening,
        s.endo_radial_contraction_percent, endo,
        s.epi_radial_contraction_percent, epi, s.myocardial_volume_ml,
        s.material_myocardium_ml, s.myocardial_volume_change_percent,
        myocardium_change);
    EXPECT_NEAR(s.wall_thickening_percent, thickening, kThickeningPoints) << t;
    EXPECT_NEAR(s.endo_radial_contraction_percent, endo, kEndoPoints) << t;
    EXPECT_NEAR(s.epi_radial_contraction_percent, epi, kEpiPoints) << t;
    if (c.geometry == LvGeometry::kCylinder) {
      EXPECT_NEAR(s.myocardial_volume_change_percent, myocardium_change,
                  kMyocardiumPercent)
          << t;
    }
    if (c.law == LvThickeningLaw::kIncompressible) {
      EXPECT_NEAR(s.myocardial_volume_change_percent, 0.0, kMyocardiumPercent)
          << t;
    }
  }
  if (c.geometry == LvGeometry::kCylinder && c.noise_mm == 0.0) {
    // Over the whole length, rings without data among them, the cylinder's
    // thickening read far off (58 % against 34 % at ES, ranked depths;
    // held, noise-free, still over 10 points).  With noise the rings
    // without data happened to read within 2-3.4 points (held, seed 1):
    // what they read there is no measurement either way.
    const size_t es = fit.frames.size() - 1;
    const ClinicalSummary whole =
        SummarizeFrame(es, analysis.models[0], analysis.models[es]);
    EXPECT_GT(std::abs(whole.wall_thickening_percent -
                       SegmentMean(phantom.truth[es].wall_thickening_percent)),
              10.0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    GeometriesLawsNoise, LvWallSegmentTest,
    testing::Values(
        Case{LvGeometry::kCylinder, LvThickeningLaw::kDesigned, 0.0},
        Case{LvGeometry::kCylinder, LvThickeningLaw::kDesigned, 0.5},
        Case{LvGeometry::kCylinder, LvThickeningLaw::kIncompressible, 0.0},
        Case{LvGeometry::kCylinder, LvThickeningLaw::kIncompressible, 0.5},
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.0},
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.5},
        Case{LvGeometry::kProlate, LvThickeningLaw::kIncompressible, 0.0},
        Case{LvGeometry::kProlate, LvThickeningLaw::kIncompressible, 0.5}));

// One seed's thickening within 3 points says little of the next, so the
// targets are checked over eight noise draws (0.5 mm) of each geometry and
// law, at frames 1 and 2.  At 1,500 tags they do not hold: on the prolate
// segment thickening erred by rms 2.6 points, worst 5.0 (designed law) and
// 4.6 (incompressible), its mean within 0.2.  That spread is the depth
// profile's: thickness is where the fitted cubic (model/transmural.h)
// meets the walls, and a least-squares cubic's endpoint varies (3 + 7) / 3
// times as much as a line's (the odd Legendre terms); holding the squeeze
// at 0 left a spread of 1.5 but read 2.4 points under (docs/gauge.md).  At
// 3,000 tags (kTags) the spread is about 1.1 points and every draw is
// within the targets.  Measured with depths held (the default), the noise
// read as stretched since frame 0 (tangential_stretch.h): thickening mean
// -0.21 / +0.04 cylinder, -0.23 / +0.05 prolate (designed /
// incompressible), worst 1.93 / 2.19, 1.79 / 1.72; each wall's radial
// contraction 1.43 points at worst.  Before that, the noise read low, the
// means were -0.82 / -0.41, -1.06 / -0.62 (docs/gauge.md, "Why held depths
// read low under noise"), which the mean's bound below fails.  Ranked anew
// in every frame: means +0.49 / +0.36, +0.87 / +0.76, worst 2.64 / 1.43,
// 2.48 / 2.67.
constexpr double kSeedsMeanThickeningPoints = 0.75;

class LvWallSegmentSeedsTest : public testing::TestWithParam<Case> {};

TEST_P(LvWallSegmentSeedsTest, TargetsHoldOverEightNoiseDraws) {
  const Case c = GetParam();
  double sum = 0.0, worst = 0.0, worst_endo = 0.0, worst_epi = 0.0;
  int count = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const LvPhantom phantom = SegmentPhantom(c, seed);
    const SequenceFit fit =
        FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
    const FitAnalysis analysis = AnalyzeFit(fit);
    for (size_t t = 1; t < fit.frames.size(); ++t) {
      const ClinicalSummary& s = analysis.clinical[t];
      const WallTruth truth = SegmentTruth(phantom.truth[t]);
      const double error = s.wall_thickening_percent - truth.thickening;
      sum += error;
      worst = std::max(worst, std::abs(error));
      worst_endo = std::max(
          worst_endo, std::abs(s.endo_radial_contraction_percent - truth.endo));
      worst_epi = std::max(
          worst_epi, std::abs(s.epi_radial_contraction_percent - truth.epi));
      ++count;
    }
  }
  std::printf(
      "%s %s: thickening mean %+.2f, worst %.2f points; endo worst %.2f, "
      "epi worst %.2f\n",
      LvGeometryName(c.geometry).c_str(), LvThickeningLawName(c.law).c_str(),
      sum / count, worst, worst_endo, worst_epi);
  EXPECT_LT(std::abs(sum / count), kSeedsMeanThickeningPoints);
  EXPECT_LT(worst, kThickeningPoints);
  EXPECT_LT(worst_endo, kEndoPoints);
  EXPECT_LT(worst_epi, kEpiPoints);
}

INSTANTIATE_TEST_SUITE_P(
    GeometriesLaws, LvWallSegmentSeedsTest,
    testing::Values(
        Case{LvGeometry::kCylinder, LvThickeningLaw::kDesigned, 0.5},
        Case{LvGeometry::kCylinder, LvThickeningLaw::kIncompressible, 0.5},
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.5},
        Case{LvGeometry::kProlate, LvThickeningLaw::kIncompressible, 0.5}));

}  // namespace
}  // namespace pfdm
