#include "pfdm/report/fit_analysis.h"

#include <algorithm>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

// The project's phantom with one tag: the analysis measures its truth's
// models (TruthAsFit), which the points do not enter.
Phantom OnePointPhantom(int num_frames = 5) {
  PhantomOptions options;
  options.num_points = 1;
  options.num_frames = num_frames;
  return MakePhantom(options);
}

TEST(FitAnalysisTest, EveryFrameIsSummarizedAgainstFrameZero) {
  const Phantom phantom = OnePointPhantom();
  const FitAnalysis analysis = AnalyzeFit(TruthAsFit(phantom));
  ASSERT_EQ(analysis.clinical.size(), 5u);
  EXPECT_TRUE(analysis.base_planes.empty());
  // tau = -5 + 7 h degrees; the rings at h = 0.2 and 0.85.
  EXPECT_NEAR(analysis.clinical[4].net_twist_deg, 7.0 * 0.65, 0.01);
  EXPECT_EQ(analysis.ejection_fraction.es_frame, 4);
  ASSERT_EQ(analysis.region_motion.size(), 5u);
  ASSERT_EQ(analysis.region_motion[4].size(), 17u);
  EXPECT_FALSE(analysis.layout.anatomical);
  EXPECT_TRUE(analysis.apex_cap_measured);
  // The phantom's a1 shrinks 20 % everywhere and a2 by 20 % at the apex to
  // 10 % at the base: every segment contracts by 10-20 %.
  for (const RegionMotion& m : analysis.region_motion[4]) {
    EXPECT_GT(m.radial_contraction_percent, 9.0);
    EXPECT_LT(m.radial_contraction_percent, 21.0);
  }
  // Apical segments turn clockwise (tau < 0), basal ones counter-clockwise.
  EXPECT_LT(analysis.region_motion[4][15].rotation_deg, -2.0);
  EXPECT_GT(analysis.region_motion[4][0].rotation_deg, 0.5);
}

// A frame without tracked points has no rotation, twist, torsion, shear
// angle, regional rotation or Ecl (kNotMeasured); its contraction, strain
// and volume are as measured.  Frame 0 without them takes every frame's.
TEST(FitAnalysisTest, FramesWithoutTrackedPointsHaveNoRotation) {
  const Phantom phantom = OnePointPhantom(3);
  SequenceFit fit = TruthAsFit(phantom);
  const FitAnalysis tracked = AnalyzeFit(fit);
  EXPECT_EQ(tracked.rotation_measured, std::vector<bool>(3, true));
  fit.frames[2].tracked = false;
  const FitAnalysis analysis = AnalyzeFit(fit);
  EXPECT_EQ(analysis.rotation_measured, std::vector<bool>({true, true, false}));
  for (int t : {0, 1}) {
    EXPECT_EQ(analysis.clinical[t].net_twist_deg,
              tracked.clinical[t].net_twist_deg);
    EXPECT_EQ(analysis.region_motion[t][15].rotation_deg,
              tracked.region_motion[t][15].rotation_deg);
  }
  EXPECT_NEAR(tracked.clinical[2].net_twist_deg, 7.0 * 0.65, 0.01);
  const ClinicalSummary& c = analysis.clinical[2];
  for (double value :
       {c.apex_rotation_deg, c.base_rotation_deg, c.net_twist_deg,
        c.torsion_deg_per_cm, c.shear_angle_deg, c.endo_net_twist_deg,
        c.epi_net_twist_deg, analysis.strain[2].gcl_percent}) {
    EXPECT_FALSE(Measured(value));
  }
  for (const RegionMotion& m : analysis.region_motion[2]) {
    EXPECT_FALSE(Measured(m.rotation_deg));
    EXPECT_FALSE(Measured(m.ecl_percent));
    EXPECT_GT(m.radial_contraction_percent, 4.0);
  }
  EXPECT_EQ(c.radial_contraction_percent,
            tracked.clinical[2].radial_contraction_percent);
  EXPECT_EQ(analysis.strain[2].gcs_percent, tracked.strain[2].gcs_percent);
  EXPECT_EQ(c.volume_ml, tracked.clinical[2].volume_ml);

  fit.frames[2].tracked = true;
  fit.frames[0].tracked = false;  // The reference of every rotation.
  EXPECT_EQ(RotationMeasured(fit), std::vector<bool>(3, false));
}

// Data that stop 49 % of the length above the apex pole (a
// mid-ventricular segment): the apical level (middle at 1/6) and the apical
// ring (at 0.2) lie below them, the mid level's middle (0.5) does not.
// What lies there is null unless shown; the rest is as measured.
TEST(FitAnalysisTest, WhatLiesBelowTheDataIsNotMeasuredUnlessShown) {
  SequenceFit fit = TruthAsFit(OnePointPhantom(3));
  const FitAnalysis full = AnalyzeFit(fit);
  EXPECT_EQ(full.level_extrapolated, (std::array<bool, 4>{}));
  fit.apex_in_data = false;
  fit.lowest_data_height = 0.49;
  const FitAnalysis analysis = AnalyzeFit(fit);
  EXPECT_EQ(analysis.level_extrapolated,
            (std::array<bool, 4>{false, false, true, true}));
  EXPECT_TRUE(analysis.apex_ring_extrapolated);
  EXPECT_FALSE(analysis.extrapolated_shown);
  const ClinicalSummary& c = analysis.clinical[2];
  for (double value :
       {c.apex_rotation_deg, c.net_twist_deg, c.torsion_deg_per_cm,
        c.shear_angle_deg, analysis.strain[2].level_ecc_percent[kApical],
        analysis.strain[2].level_ell_percent[kApical]}) {
    EXPECT_FALSE(Measured(value));
  }
  EXPECT_EQ(c.base_rotation_deg, full.clinical[2].base_rotation_deg);
  EXPECT_EQ(c.volume_ml, full.clinical[2].volume_ml);
  EXPECT_EQ(analysis.strain[2].gcs_percent, full.strain[2].gcs_percent);
  EXPECT_EQ(analysis.strain[2].level_ecc_percent[kMid],
            full.strain[2].level_ecc_percent[kMid]);
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    const RegionMotion& m = analysis.region_motion[2][r];
    const bool apical = analysis.regions[r].level == kApical ||
                        analysis.regions[r].level == kApex;
    EXPECT_EQ(Measured(m.ecc_percent), !apical) << r;
    EXPECT_EQ(Measured(m.radial_contraction_percent), !apical) << r;
    EXPECT_EQ(Measured(m.rotation_deg), !apical) << r;
  }
  const FitAnalysis shown =
      AnalyzeFit(fit, {}, RegionLayout(), /*show_extrapolated=*/true);
  EXPECT_TRUE(shown.extrapolated_shown);
  EXPECT_EQ(shown.clinical[2].net_twist_deg, full.clinical[2].net_twist_deg);
  EXPECT_EQ(shown.region_motion[2][15].ecc_percent,
            full.region_motion[2][15].ecc_percent);

  // The apical level lies above the cap (0.1 to 1/3 of the length): its
  // middle, 0.217, is above data from 0.21.
  fit.lowest_data_height = 0.21;
  EXPECT_FALSE(AnalyzeFit(fit).level_extrapolated[kApical]);
  fit.lowest_data_height = 0.1;  // Below the ring: only the cap.
  const FitAnalysis low = AnalyzeFit(fit);
  EXPECT_EQ(low.level_extrapolated,
            (std::array<bool, 4>{false, false, false, true}));
  EXPECT_FALSE(low.apex_ring_extrapolated);
}

// Without data near the apex (SequenceFit::apex_in_data) the apex cap's
// numbers are not measured, its area kept; the apical level's strain and
// the global strain still take the model's cap in, as they did.
TEST(FitAnalysisTest, ApexCapIsNotMeasuredWithoutDataNearTheApex) {
  const Phantom phantom = OnePointPhantom();
  SequenceFit fit = TruthAsFit(phantom);
  const FitAnalysis seen = AnalyzeFit(fit);
  fit.apex_in_data = false;
  const FitAnalysis unseen = AnalyzeFit(fit);
  EXPECT_FALSE(unseen.apex_cap_measured);
  ASSERT_EQ(unseen.regions[16].level, kApex);
  EXPECT_GT(seen.region_motion[4][16].radial_contraction_percent, 9.0);
  for (size_t t = 0; t < 5; ++t) {
    const RegionMotion& cap = unseen.region_motion[t][16];
    for (double value : {cap.rotation_deg, cap.radial_contraction_percent,
                         cap.ecc_percent, cap.ell_percent, cap.ecl_percent}) {
      EXPECT_FALSE(Measured(value)) << t;
    }
    EXPECT_EQ(cap.area_mm2, seen.region_motion[t][16].area_mm2);
    EXPECT_EQ(unseen.strain[t].gcs_percent, seen.strain[t].gcs_percent);
    EXPECT_EQ(unseen.strain[t].level_ecc_percent[kApical],
              seen.strain[t].level_ecc_percent[kApical]);
    EXPECT_EQ(unseen.region_motion[t][15].ecc_percent,
              seen.region_motion[t][15].ecc_percent);
  }
}

TEST(FitAnalysisTest, BasePlanesReplaceTheFlatLidsVolumes) {
  const Phantom phantom = OnePointPhantom();
  // A plane across the axis 10 mm below each frame's centre.
  std::vector<BasePlane> planes;
  for (const Model& model : phantom.truth) {
    const Eigen::Vector3d axis = model.Rotation().col(2);
    planes.push_back(
        {Eigen::Vector3d(model.state.center.data()) - 10.0 * axis, axis, 6});
  }
  const FitAnalysis analysis = AnalyzeFit(TruthAsFit(phantom), planes);
  ASSERT_EQ(analysis.base_planes.size(), 5u);
  for (size_t t = 0; t < 5; ++t) {
    EXPECT_DOUBLE_EQ(analysis.clinical[t].volume_ml,
                     CavityVolumeMl(phantom.truth[t], &planes[t]));
    EXPECT_LT(analysis.clinical[t].volume_ml, CavityVolumeMl(phantom.truth[t]));
  }
}

// Both walls' short-axis contours (noise-free LV phantom): the fit puts
// the solid's lowest rim, the endocardium's, at the highest slice
// (RimLift), its walls end there, and its cavity is the endocardial
// contours' alone to 1.5 ml (end-systole 40.4 against 41.6; 42.4 against
// 42.2 while untracked frames' length was held at frame 0's).  The rim
// residual is soft: at end-systole the rim ends 0.5 mm above the slice (a
// surface's on the endocardial contours 0.3 mm).  With the mid-wall's rim at
// the slice, the endocardium's lay 1.3-1.8 mm below it, frame 0 read RMS 0.47
// mm (now 0.12) and each wall's flat lid at its own rim 1.6-1.8 ml under.  Tags
// through the wall end on a surface across it, as the walls' rims do: no slice
// plane.
TEST(FitAnalysisTest, ASolidsWallsEndAtTheHighestSlice) {
  LvPhantomOptions phantom;
  phantom.sampling = LvSampling::kSaxSlices;
  phantom.tags = LvTagLayer::kWall;
  phantom.num_frames = 2;
  phantom.noise_mm = 0.0;
  const PointSequence walls = MakeLvPhantom(phantom).points;
  PointSequence endo = walls;
  for (Frame& frame : endo.frames) {
    auto& points = frame.points;
    points.erase(std::remove_if(points.begin(), points.end(),
                                [](const DataPoint& p) {
                                  return p.layer == WallLayer::kEpicardium;
                                }),
                 points.end());
  }
  FitOptions options;
  options.local.enabled = false;
  const SequenceFit solid = FitSequence(walls, ModelConfig::Paper(9), options);
  ASSERT_TRUE(solid.config.Solid());
  const FitAnalysis analysis = AnalyzeFit(solid);
  const FitAnalysis endo_analysis =
      AnalyzeFit(FitSequence(endo, ModelConfig::Paper(9), options));
  for (size_t t = 0; t < 2; ++t) {
    const BasePlane* plane = VolumePlaneOf(analysis, t);
    ASSERT_NE(plane, nullptr) << t;
    const double volume = analysis.clinical[t].volume_ml;
    EXPECT_NEAR(volume, endo_analysis.clinical[t].volume_ml, 1.5) << t;
    const Eigen::Vector3d axis = analysis.models[t].Rotation().col(2);
    double top = -1e9;
    for (const DataPoint& p : walls.frames[t].points) {
      top = std::max(top, axis.dot(p.position));
    }
    EXPECT_NEAR(axis.dot(plane->point), top, 0.6) << t;
    EXPECT_EQ(solid.frames[t].unsettled_mm, 0.0) << t;
  }
  EXPECT_LT(solid.frames[0].rms_mm, 0.2);
  phantom.sampling = LvSampling::kTags;
  phantom.num_tags = 1000;
  const FitAnalysis tags = AnalyzeFit(FitSequence(
      MakeLvPhantom(phantom).points, ModelConfig::Paper(9), options));
  ASSERT_TRUE(tags.models[0].config.Solid());
  EXPECT_EQ(VolumePlaneOf(tags, 0), nullptr);
  EXPECT_EQ(VolumePlaneOf(tags, 1), nullptr);
}

// A frame whose data span too little of the axis (short_span) has no
// volume, and then the ejection fraction has no ESV nor ratio, whichever
// frame it is: end-systole may be that frame (the LV phantom's three
// short-axis slices lost the basal one at ES).  --extrapolated shows them.
TEST(FitAnalysisTest, AFrameSpanningTooLittleOfTheAxisHasNoVolume) {
  const Phantom phantom = OnePointPhantom();
  SequenceFit fit = TruthAsFit(phantom);
  const FitAnalysis full = AnalyzeFit(fit);
  ASSERT_EQ(full.ejection_fraction.es_frame, 4);
  EXPECT_GT(full.ejection_fraction.ratio, 0.2);
  EXPECT_EQ(full.volume_measured, std::vector<bool>(5, true));

  fit.frames[4].verdict.Warn(kShortSpanCode, "the data span 53 %");
  const FitAnalysis analysis = AnalyzeFit(fit);
  EXPECT_EQ(analysis.volume_measured,
            std::vector<bool>({true, true, true, true, false}));
  EXPECT_FALSE(Measured(analysis.clinical[4].volume_ml));
  EXPECT_FALSE(Measured(analysis.clinical[4].lv_mass_g));
  for (int t : {0, 1, 2, 3}) {
    EXPECT_EQ(analysis.clinical[t].volume_ml, full.clinical[t].volume_ml);
  }
  // The rest of the frame is as measured.
  EXPECT_EQ(analysis.clinical[4].radial_contraction_percent,
            full.clinical[4].radial_contraction_percent);
  const EjectionFraction& ef = analysis.ejection_fraction;
  EXPECT_EQ(ef.es_frame, 3);  // The least of the volumes there are.
  EXPECT_EQ(ef.edv_ml, full.ejection_fraction.edv_ml);
  EXPECT_FALSE(Measured(ef.esv_ml));
  EXPECT_FALSE(Measured(ef.ratio));
  // A missing volume is no implausible one.
  EXPECT_FALSE(analysis.verdicts[4].Has("volume_range"));

  // A frame before end-systole: the ES frame stays, its ratio goes.
  fit.frames[4].verdict = Verdict();
  fit.frames[2].verdict.Warn(kShortSpanCode, "the data span 53 %");
  const FitAnalysis middle = AnalyzeFit(fit);
  EXPECT_EQ(middle.ejection_fraction.es_frame, 4);
  EXPECT_FALSE(Measured(middle.ejection_fraction.ratio));

  const FitAnalysis shown =
      AnalyzeFit(fit, {}, RegionLayout(), /*show_extrapolated=*/true);
  EXPECT_EQ(shown.volume_measured, std::vector<bool>(5, true));
  EXPECT_EQ(shown.ejection_fraction.ratio, full.ejection_fraction.ratio);
}

// The ring means go where frame 0 has data when it does not reach the apex,
// over the whole length otherwise or when asked to show extrapolations.
TEST(FitAnalysisTest, RingSpanFollowsTheData) {
  SequenceFit fit;
  fit.apex_in_data = true;
  fit.lowest_data_height = 0.4;
  fit.highest_data_height = 0.9;
  RingSpan span = ClinicalRingSpan(fit, false);
  EXPECT_EQ(span.low, 0.0);
  EXPECT_EQ(span.high, 1.0);
  EXPECT_NEAR(span.At(0), 0.05, 1e-12);
  fit.apex_in_data = false;
  span = ClinicalRingSpan(fit, false);
  EXPECT_EQ(span.low, 0.4);
  EXPECT_EQ(span.high, 0.9);
  EXPECT_NEAR(span.At(0), 0.425, 1e-12);
  EXPECT_NEAR(span.At(kContractionRings - 1), 0.875, 1e-12);
  EXPECT_EQ(ClinicalRingSpan(fit, true).low, 0.0);
  fit.highest_data_height = 1.3;  // Data past the rim: the rim.
  EXPECT_EQ(ClinicalRingSpan(fit, false).high, 1.0);
  fit.lowest_data_height = 0.98;  // Too thin a band: the whole length.
  EXPECT_EQ(ClinicalRingSpan(fit, false).low, 0.0);
}

}  // namespace
}  // namespace pfdm
