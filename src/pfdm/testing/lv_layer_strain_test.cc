// Strain per layer (report/layer_strain.h) of a solid fitted to the LV
// phantom's tags through the wall, against the phantom's own per-layer
// truth (phantom/lv_layer_truth.h, measured on its material points from
// its analytic motion): each segment's Ecc, Ell and Err at the
// endocardium, mid-wall and epicardium, each third's thickening and Err
// across the wall, at every frame.
//
// Measured (segments 1-16, every frame; the tolerances below): each
// layer's Ecc within 2.2-4.4 points and Ell within 2.6 on the prolate
// shell, within the 3.5 points for the designed law (the
// cylinder's epicardial Ell is 6.1-6.5 off: -4.9 to -7.5 % against -11.0 at
// every height); Err across the wall within 5.5-9.4 points and each third's
// thickening only within 10-17 points, also without noise (13.8): the
// fitted depth profile does not follow the phantom's per segment, as the
// segments' whole-wall thickening already shows (noise-free, ES: basal
// 50.0 % against 45.9, mid 39.0 against 44.2).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_json.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/phantom/lv_cylinder.h"
#include "pfdm/phantom/lv_layer_truth.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// Tolerances (points) over segments 1-16 and every frame, from what was
// measured (in brackets below); the apex cap is printed, not held to them.
struct Case {
  LvGeometry geometry;
  LvThickeningLaw law;
  double noise_mm;
  double ecc, ell, thickening, err;
  LvSampling sampling = LvSampling::kTags;
};

// Worst |fit - truth| over the frames and measured segments, per quantity.
struct Worst {
  double ecc[3] = {}, ell[3] = {}, thickening[3] = {};
  double err = 0.0;
  int compared = 0;
};

void Track(double fit, double truth, double* worst) {
  *worst = std::max(*worst, std::abs(fit - truth));
}

// Over segments 1-16 (cap false) or the apex cap alone (true).
Worst Compare(const FitAnalysis& analysis, const LvPhantom& phantom,
              const std::vector<std::vector<LvSegmentLayers>>& truth,
              bool cap) {
  Worst worst;
  for (size_t t = 0; t < analysis.region_layers.size(); ++t) {
    const size_t es = analysis.region_layers.size() - 1;
    for (size_t r = 0; r < analysis.regions.size(); ++r) {
      if ((analysis.regions[r].level == kApex) != cap) continue;
      const RegionLayers& fit = analysis.region_layers[t][r];
      const LvSegmentLayers& real = truth[t][r];
      if (std::isnan(fit.err_percent) || std::isnan(real.err_percent)) {
        continue;
      }
      ++worst.compared;
      Track(fit.err_percent, real.err_percent, &worst.err);
      if (t == es) {
        std::printf(
            "ES %-10s Err across the wall %6.1f (%6.1f), the wall's "
            "thickening %6.1f (%6.1f)\n",
            analysis.regions[r].Name().c_str(), fit.err_percent,
            real.err_percent, analysis.region_motion[t][r].thickening_percent,
            r < phantom.truth[t].segments.size()
                ? phantom.truth[t].segments[r].wall_thickening_percent
                : NAN);
      }
      for (int k = 0; k < kWallLayers; ++k) {
        const LayerStrain& f = fit.layers[k];
        const LvLayerValues& g = real.layers[k];
        Track(f.ecc_percent, g.ecc_percent, &worst.ecc[k]);
        Track(f.ell_percent, g.ell_percent, &worst.ell[k]);
        Track(f.thickening_percent, g.thickening_percent, &worst.thickening[k]);
        if (t == es) {
          std::printf(
              "ES %-10s %-11s Ecc %6.1f (%6.1f) Ell %6.1f (%6.1f) "
              "thickening %6.1f (%6.1f)\n",
              analysis.regions[r].Name().c_str(), kLayerNames[k], f.ecc_percent,
              g.ecc_percent, f.ell_percent, g.ell_percent, f.thickening_percent,
              g.thickening_percent);
        }
      }
    }
  }
  return worst;
}

class LvLayerStrainTest : public testing::TestWithParam<Case> {};

TEST_P(LvLayerStrainTest, EachLayerOfEachSegmentAgainstThePhantoms) {
  const Case c = GetParam();
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.geometry = c.geometry;
  options.law = c.law;
  options.noise_mm = c.noise_mm;
  options.sampling = c.sampling;
  if (c.geometry == LvGeometry::kCylinder) {
    options.deformation = CylinderDeformation();
    options.num_tags = 1500;
    options.num_frames = 3;
  }
  const LvPhantom phantom = MakeLvPhantom(options);
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
  ASSERT_TRUE(fit.config.Solid()) << fit.wall_reason;
  const FitAnalysis analysis = AnalyzeFit(fit);
  ASSERT_EQ(analysis.region_layers.size(), fit.frames.size());
  const auto truth = MeasureLvLayerTruth(phantom);
  for (bool cap : {false, true}) {
    const Worst worst = Compare(analysis, phantom, truth, cap);
    std::printf(
        "%s %s noise %.1f, %s, worst over %d segment-frames (endo, mid, "
        "epi): Ecc %.2f %.2f %.2f  Ell %.2f %.2f %.2f  thickening %.2f %.2f "
        "%.2f  Err %.2f\n",
        LvGeometryName(c.geometry).c_str(), LvThickeningLawName(c.law).c_str(),
        c.noise_mm, cap ? "apex cap" : "segments 1-16", worst.compared,
        worst.ecc[0], worst.ecc[1], worst.ecc[2], worst.ell[0], worst.ell[1],
        worst.ell[2], worst.thickening[0], worst.thickening[1],
        worst.thickening[2], worst.err);
    if (cap) continue;
    EXPECT_GT(worst.compared, 0);
    for (int k = 0; k < kWallLayers; ++k) {
      EXPECT_LT(worst.ecc[k], c.ecc) << kLayerNames[k];
      EXPECT_LT(worst.ell[k], c.ell) << kLayerNames[k];
      EXPECT_LE(worst.thickening[k], c.thickening) << kLayerNames[k];
    }
    EXPECT_LT(worst.err, c.err);
  }
  if (c.sampling == LvSampling::kSaxSlices) {
    // The layers inside the wall are not seen: no third's thickening.
    EXPECT_TRUE(
        std::isnan(analysis.region_layers[1][7].layers[1].thickening_percent));
  }
  // fit.json holds them: the endocardial Ecc at ES of the first segment
  // measured there, from mid 2 on (the cylinder's data, without an apex,
  // may not reach far enough into the model's mid third: its extrapolated
  // apex sets the levels), and its Err.
  const auto json = nlohmann::json::parse(
      FitJson(phantom.points, fit, FitOptions(), analysis));
  const size_t es = fit.frames.size() - 1;
  size_t r = 7;
  while (r > 0 &&
         std::isnan(analysis.region_layers[es][r].layers[0].ecc_percent)) {
    --r;
  }
  const RegionLayers& measured = analysis.region_layers[es][r];
  ASSERT_FALSE(std::isnan(measured.layers[0].ecc_percent));
  EXPECT_EQ(json["regions"][r]["layers"]["endocardium"]["ecc_percent"][es]
                .get<double>(),
            measured.layers[0].ecc_percent);
  EXPECT_EQ(json["regions"][r]["err_percent"][es].get<double>(),
            measured.err_percent);
  EXPECT_TRUE(json.contains("layers_definition"));
}

INSTANTIATE_TEST_SUITE_P(
    GeometriesLawsNoise, LvLayerStrainTest,
    testing::Values(
        // Measured: Ecc 2.83, Ell 2.59, thirds 16.3, Err 8.1.
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.5, 3.5, 3.0,
             18.0, 9.0},
        // Ecc 2.21, Ell 2.37, thirds 13.8, Err 7.6: the method, not noise.
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.0, 3.5, 3.0,
             15.0, 9.0},
        // Ecc 4.34 (endocardium), Ell 2.51, thirds 15.8, Err 9.5.  Which
        // tags a segment holds moves with frame 0's spin, which the data
        // of this round phantom leave free: over seeds 1-8 the worst
        // endocardial Ecc read 3.35-4.38 with the spin the rounds crept to
        // and 3.08-4.34 with the start's (frame_fit.cc), the thirds up to
        // 24 either way.  The bounds are seed 1's.
        Case{LvGeometry::kProlate, LvThickeningLaw::kIncompressible, 0.5, 4.5,
             3.0, 17.0, 10.5},
        // Ecc 3.54, Ell 6.51 (epicardium), thirds 15.8, Err 5.0.  Over seeds
        // 1-8 the epicardial Ell read 2.0-7.6 (crept spin) and 4.8-8.2
        // (the start's), the endocardial Ecc 2.4-4.1 and 2.6-4.5.
        Case{LvGeometry::kCylinder, LvThickeningLaw::kDesigned, 0.5, 4.0, 7.0,
             18.0, 6.5},
        // Ecc 3.54, Ell 5.53, thirds 17.1, Err 5.5-7.1: the tags' depth
        // ranks are found again each round from the model, so the path
        // matters; the linear solver alone (DENSE_SCHUR, the default, vs
        // SPARSE_NORMAL_CHOLESKY) moves Err from 6.0 to 7.1.
        Case{LvGeometry::kCylinder, LvThickeningLaw::kIncompressible, 0.5, 4.0,
             6.5, 18.5, 7.5},
        // Both walls' contours on 9 short-axis slices, untracked: Ecc 5.3 /
        // 8.6 / 4.3, Ell 7.7 / 8.5 / 9.1, Err 6.2; the thirds n/a.  The
        // mid-wall's Ecc is furthest (apical -12.6 against -20.4): the
        // solid's geometric mid-wall is not the phantom's material one.
        // The untracked frames' pull toward frame 0's radii, at 0.3 where
        // the slices cover a ring (FitOptions::
        // untracked_prior_covered_radii_scale), read every layer's Ecc
        // further under at full strength (6.3 / 9.5 / 5.2, Err 7.2, apical
        // mid-wall -11.2) and the epicardium's worst Ell 8.6.  Since that
        // pull leaves the length to the data (the apex in them), ES's model
        // is as long as its slices say: Ell follows the truth (-14.9
        // against -15.4 at mid) and the apical segments' Err reads 45.6
        // against 43.8 (Err 17.6 and Ell 9.9 while ES was held 6 mm too
        // long, its apex cap thinned).
        Case{LvGeometry::kProlate, LvThickeningLaw::kDesigned, 0.5, 9.5, 9.5,
             0.0, 7.0, LvSampling::kSaxSlices}));

// A mid-wall surface has no wall: no layers at all, not zeros.
TEST(LvLayerStrainTest, AMidWallFitHasNoLayers) {
  LvPhantomOptions options;
  options.num_tags = 800;
  options.num_frames = 3;
  const LvPhantom phantom = MakeLvPhantom(options);
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
  ASSERT_FALSE(fit.config.Solid());
  const FitAnalysis analysis = AnalyzeFit(fit);
  EXPECT_TRUE(analysis.region_layers.empty());
  const auto json = nlohmann::json::parse(
      FitJson(phantom.points, fit, FitOptions(), analysis));
  EXPECT_FALSE(json["regions"][7].contains("layers"));
  EXPECT_FALSE(json["regions"][7].contains("err_percent"));
  EXPECT_FALSE(json.contains("layers_definition"));
}

// biv-me patient 1's endocardial and epicardial contours (25 frames, as
// `pfdm fit --contours lv-cavity,lv-epi`): a solid with layers, no third's
// thickening (contours), and at ES every mid segment's endocardium
// shortening more than its epicardium, as a heart's does (measured: -22.8
// to -28.5 % against -6.1 to -10.0; Err across the wall 101 %).
TEST(LvLayerStrainTest, BivMeBothWallsEndocardiumShortensMost) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  FitOptions options;
  AddLandmarkAxis(gp, &options);
  const SequenceFit fit =
      FitSequence(ReadGpFiles(gp, ExpandContourAlias("lv-cavity,lv-epi")),
                  ModelConfig::Paper(17), options);
  ASSERT_TRUE(fit.config.Solid()) << fit.wall_reason;
  const FitAnalysis analysis = AnalyzeFit(fit);
  ASSERT_EQ(analysis.region_layers.size(), 25u);
  const size_t es = analysis.ejection_fraction.es_frame;
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    if (analysis.regions[r].level != kMid) continue;
    const RegionLayers& layers = analysis.region_layers[es][r];
    std::printf("biv-me ES %s: Ecc %.1f %.1f %.1f, Err %.1f\n",
                analysis.regions[r].Name().c_str(),
                layers.layers[0].ecc_percent, layers.layers[1].ecc_percent,
                layers.layers[2].ecc_percent, layers.err_percent);
    EXPECT_LT(layers.layers[0].ecc_percent, layers.layers[2].ecc_percent - 5.0)
        << analysis.regions[r].Name();
    EXPECT_TRUE(std::isnan(layers.layers[1].thickening_percent));
  }
}

}  // namespace
}  // namespace pfdm
