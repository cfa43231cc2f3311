// The solid (model/transmural.h) fitted to tags through the wall of a
// mid-ventricular segment, no apex (issue 32): the cylinder and the prolate
// shell's segment (lv_phantom.h), each wall under both thickening laws
// (lv_motion.h), with and without noise.  The clinical ring means are taken
// where frame 0 has data (ClinicalRingSpan), the truth's over the segment's
// heights; thickening and each wall's radial contraction are checked at
// every frame.
//
// Issue 32's targets: thickening within 3 points at every frame, each
// wall's radial contraction within 2.  Measured (1,500 tags, 3 frames;
// docs/gauge.md "The profile across the wall"), with the squeeze (a cubic
// depth) and its noise taken out: thickening 2.4 points off at worst
// (prolate, designed law, noise-free, ES: 41.7 against 44.1), endocardium
// 1.8 (prolate, incompressible: 27.0 against 28.8), epicardium 0.9.  That
// is the default seed's: on the prolate segment with 0.5 mm of noise, seeds
// 1-8 read thickening rms 2.6 points off, worst 5.0 (designed law) and 4.6
// (incompressible) (docs/performance.md, twenty-first session).  Before,
// with a quadratic depth, thickening read up to 3.9 points under and the
// endocardium 2.2.
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

struct Case {
  LvGeometry geometry;
  LvThickeningLaw law;
  double noise_mm;
};

// The segment's 1,500 tags through the wall over 3 frames.
LvPhantom SegmentPhantom(const Case& c, unsigned seed = 1) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.region = LvRegion::kMidventricular;
  options.geometry = c.geometry;
  options.law = c.law;
  options.noise_mm = c.noise_mm;
  options.num_frames = 3;
  options.num_tags = 1500;
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
    const double thickening = SegmentMean(truth.wall_thickening_percent);
    const double endo = SegmentMean(truth.endo.radial_contraction_percent);
    const double epi = SegmentMean(truth.epi.radial_contraction_percent);
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
  if (c.geometry == LvGeometry::kCylinder) {
    // Over the whole length, rings without data among them, the cylinder's
    // thickening read far off (58 % against 34 % at ES).
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

// One seed's thickening within 3 points says little of the next: over
// eight noise draws of the prolate segment (0.5 mm, 1,500 tags, frames 1
// and 2 against the truth) each law's error is measured as a spread.
// Measured: mean +0.14 and +0.21 points, rms 2.59 and 2.64, worst 4.97
// and 4.57 (designed, incompressible).  A change that made frame 0's
// held depths hang on its path (a Gauss-Newton step a round; 2026-12-04)
// read rms 4.0-4.5 and worst 11-12.
class LvWallSegmentSeedsTest : public testing::TestWithParam<LvThickeningLaw> {
};

TEST_P(LvWallSegmentSeedsTest, ThickeningOverEightNoiseDraws) {
  double sum = 0.0, sum_squares = 0.0, worst = 0.0;
  int count = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const LvPhantom phantom =
        SegmentPhantom({LvGeometry::kProlate, GetParam(), 0.5}, seed);
    const SequenceFit fit =
        FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
    const FitAnalysis analysis = AnalyzeFit(fit);
    for (size_t t = 1; t < fit.frames.size(); ++t) {
      const double error =
          analysis.clinical[t].wall_thickening_percent -
          SegmentMean(phantom.truth[t].wall_thickening_percent);
      sum += error;
      sum_squares += error * error;
      worst = std::max(worst, std::abs(error));
      ++count;
    }
  }
  const double rms = std::sqrt(sum_squares / count);
  std::printf("%s: thickening mean %+.2f, rms %.2f, worst %.2f points\n",
              LvThickeningLawName(GetParam()).c_str(), sum / count, rms, worst);
  EXPECT_LT(std::abs(sum / count), 1.0);
  EXPECT_LT(rms, 3.0);
  EXPECT_LT(worst, 6.0);
}

INSTANTIATE_TEST_SUITE_P(Laws, LvWallSegmentSeedsTest,
                         testing::Values(LvThickeningLaw::kDesigned,
                                         LvThickeningLaw::kIncompressible));

}  // namespace
}  // namespace pfdm
