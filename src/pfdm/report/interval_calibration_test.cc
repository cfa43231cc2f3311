#include "pfdm/report/interval_calibration.h"

#include <algorithm>

#include "gtest/gtest.h"
#include "pfdm/report/number_sd.h"

namespace pfdm {
namespace {

bool Has(IntervalData data, const std::string& key) {
  return KeyCalibration(data, key) == Calibration::kCalibrated;
}

bool In(const std::vector<std::string>& names, const std::string& key) {
  return std::find(names.begin(), names.end(), key) != names.end();
}

constexpr IntervalData kAll[] = {
    IntervalData::kMidwallTags, IntervalData::kWallTags,
    IntervalData::kContours,    IntervalData::kEndoContours,
    IntervalData::kEpiContours, IntervalData::kMidwallContours,
    IntervalData::kOther};

// Every calibrated key names a number fit.json gives an interval: a
// frame's clinical or strain number, a segment's, the ejection's ratio,
// EDV or ESV, or a peak of those.
TEST(IntervalCalibrationTest, KeysAreFitJsonsNames) {
  for (IntervalData data : kAll) {
    for (const std::string& key : CalibratedIntervalKeys(data)) {
      const std::string name = key.rfind("peak_", 0) == 0 ? key.substr(5) : key;
      EXPECT_TRUE(In(ClinicalFieldNames(), name) ||
                  In(StrainFieldNames(), name) ||
                  In(RegionFieldNames(), name) || name == "ratio" ||
                  name == "edv_ml" || name == "esv_ml")
          << IntervalDataName(data) << ": " << key;
    }
  }
}

// What docs/uncertainty_calibration.md measured, kind by kind.
TEST(IntervalCalibrationTest, TheCalibratedByKindOfData) {
  using D = IntervalData;
  // Tags on the mid-wall: the global numbers and the segments'.
  for (const char* key :
       {"ratio", "net_twist_deg", "gls_percent", "ecc_percent", "ell_percent",
        "rotation_deg", "longitudinal_shortening_percent"}) {
    EXPECT_TRUE(Has(D::kMidwallTags, key)) << key;
  }
  // Above issue 30's 98 %: GCS on mid-wall tags (0.99).  On one surface's
  // contours, the endocardium's and the mid-wall's, it read 0.99 too while
  // untracked frames' covered radii were pulled toward frame 0's as hard
  // as the rest, 0.95 and 0.96 since; the segments' Ell on both walls'
  // contours (0.981) and on the endocardium's (0.987) came within it once
  // the length was the data's (0.952, 0.959).
  EXPECT_FALSE(Has(D::kMidwallTags, "gcs_percent"));
  EXPECT_FALSE(Has(D::kMidwallTags, "peak_gcs_percent"));
  for (D data : {D::kEndoContours, D::kMidwallContours}) {
    EXPECT_TRUE(Has(data, "gcs_percent"));
    EXPECT_TRUE(Has(data, "peak_gcs_percent"));
    EXPECT_TRUE(Has(data, "ell_percent"));
  }
  EXPECT_TRUE(Has(D::kContours, "ell_percent"));
  // Tags through the wall at held depths (the default since 2026-12-07):
  // shortening's and the segments' thickening's intervals came within 90-98
  // % (0.98, 0.97-0.975; ranked 0.98 and 0.989); with the held depths'
  // noise in the tracked frame's covariance the wall's thickening's
  // 0.94-0.95 (0.89-0.90 without) and GCS's 0.95 (0.90-0.92); twist's and
  // the frames' radial contraction's 0.99 (too wide).  Over 300 draws the
  // net twist and torsion 0.97-0.98 (claimed), the volume fraction 0.987
  // without the lesion and radial contraction 0.987 (too wide).  With the
  // tracked frame's response to ED (2026-12-08) radial contraction 0.977
  // (claimed), ESV 0.990-0.993 (too wide, no longer).  With ED's noise
  // through the held depths counted once ESV 0.967 and the volume fraction
  // 0.967-0.970 (claimed).
  EXPECT_TRUE(Has(D::kWallTags, "net_twist_deg"));
  EXPECT_TRUE(Has(D::kWallTags, "torsion_deg_per_cm"));
  EXPECT_TRUE(Has(D::kWallTags, "ratio"));
  EXPECT_TRUE(Has(D::kWallTags, "wall_thickening_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "peak_gcs_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "gls_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "thickening_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "longitudinal_shortening_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "radial_contraction_percent"));
  EXPECT_TRUE(Has(D::kWallTags, "esv_ml"));
  EXPECT_TRUE(Has(D::kWallTags, "gcs_percent"));
  // Contours: no turn about the axis is seen.  Each later frame's own
  // length draws (its base rim is held at its highest points) took GLS
  // from 0.78 to 0.97 and shortening from 0.77 to 0.97.
  EXPECT_TRUE(Has(D::kContours, "gcs_percent"));
  EXPECT_TRUE(Has(D::kContours, "ecc_percent"));
  EXPECT_FALSE(Has(D::kContours, "rotation_deg"));
  EXPECT_TRUE(Has(D::kContours, "gls_percent"));
  EXPECT_TRUE(Has(D::kContours, "longitudinal_shortening_percent"));
  // Frame 0's length draws brought EDV to 0.90 on mid-wall tags and
  // contours; ESV stayed at 0.88 on mid-wall tags (0.89 with the apex's
  // term), and reached 0.97 on contours with the later frames' draws.  With
  // the contours' field held to the normal (2026-12-04) EDV on contours
  // read 0.89; with the apex's term in frame 0's length, 0.91.  Mid-wall
  // tags' ESV held in 0.947 and 0.953 over 300 draws (2026-12-07).
  EXPECT_TRUE(Has(D::kMidwallTags, "edv_ml"));
  EXPECT_TRUE(Has(D::kContours, "edv_ml"));
  EXPECT_TRUE(Has(D::kMidwallTags, "esv_ml"));
  EXPECT_TRUE(Has(D::kContours, "esv_ml"));
  EXPECT_TRUE(Has(D::kContours, "lv_mass_g"));
  EXPECT_TRUE(Has(D::kWallTags, "lv_mass_g"));
  EXPECT_TRUE(Has(D::kWallTags, "edv_ml"));
  // The endocardium's contours alone: every number they measure held the
  // noise-free fit in 90-96 % of draws, EDV included; one surface has no
  // wall to thicken or weigh, and no turn about the axis is seen.
  for (const char* key :
       {"ratio", "edv_ml", "esv_ml", "longitudinal_shortening_percent",
        "radial_contraction_percent", "gcs_percent", "gls_percent",
        "ecc_percent"}) {
    EXPECT_TRUE(Has(D::kEndoContours, key)) << key;
  }
  for (const char* key : {"wall_thickening_percent", "lv_mass_g",
                          "thickening_percent", "rotation_deg"}) {
    EXPECT_FALSE(Has(D::kEndoContours, key)) << key;
  }
  // The mid-wall's contours alone and the epicardium's: every number they
  // measure, the volumes and their ratio since the length's derivative is
  // the top's rise (mid-wall ESV 0.94 and ratio 0.91, epicardial EDV,
  // ESV and ratio 0.95, 0.94, 0.92; 0.87-0.89 with a uniform stretch); no
  // wall, no turn seen.
  for (D data : {D::kMidwallContours, D::kEpiContours}) {
    for (const char* key :
         {"ratio", "edv_ml", "esv_ml", "longitudinal_shortening_percent",
          "radial_contraction_percent", "gcs_percent", "gls_percent",
          "ecc_percent", "ell_percent"}) {
      EXPECT_TRUE(Has(data, key)) << key;
    }
    for (const char* key :
         {"wall_thickening_percent", "lv_mass_g", "thickening_percent",
          "rotation_deg", "net_twist_deg"}) {
      EXPECT_FALSE(Has(data, key)) << key;
    }
  }
  // No kind's apex rotation or shear angle was shown calibrated, and
  // nothing on data of another kind.
  for (IntervalData data : kAll) {
    for (const char* key :
         {"apex_rotation_deg", "shear_angle_deg", "volume_ml"}) {
      EXPECT_FALSE(Has(data, key)) << IntervalDataName(data) << ": " << key;
    }
  }
  EXPECT_TRUE(CalibratedIntervalKeys(D::kOther).empty());
}

// The kind from the fit: tags where every frame is tracked, by whether the
// model is a solid; contours where none is, of both walls (a solid) or of
// the endocardium; a mix (tracked and untracked frames, or contours beside
// tags in a frame) is neither.
TEST(IntervalCalibrationTest, KindOfTheFitsData) {
  SequenceFit fit;
  fit.config = ModelConfig::Paper(9);
  fit.frames.resize(3);
  ASSERT_FALSE(fit.config.Solid());
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kMidwallTags);
  fit.config.MakeSolid();
  ASSERT_TRUE(fit.config.Solid());
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kWallTags);
  // Contours beside the tags in a tracked frame: a mix.
  fit.frames[1].mixed = true;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kOther);
  fit.frames[1].mixed = false;
  for (FrameFit& f : fit.frames) f.tracked = false;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kContours);
  fit.frames[0].tracked = true;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kOther);
  // One surface's contours: by its wall, the endocardium's, the
  // epicardium's or the mid-wall's (a surface of neither wall).
  fit.config = ModelConfig::Paper(9);
  for (FrameFit& f : fit.frames) f.tracked = false;
  fit.surface = WallLayer::kEndocardium;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kEndoContours);
  fit.surface = WallLayer::kEpicardium;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kEpiContours);
  fit.surface = WallLayer::kAnywhere;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kMidwallContours);
  fit.frames[2].tracked = true;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kOther);
  fit.frames[2].tracked = false;
  fit.surface = WallLayer::kEndocardium;
  fit.frames[1].tracked = true;
  EXPECT_EQ(IntervalDataOf(fit), IntervalData::kOther);
  EXPECT_EQ(IntervalDataName(IntervalData::kContours), "wall contours");
  EXPECT_EQ(IntervalDataName(IntervalData::kEndoContours),
            "endocardial contours");
  EXPECT_EQ(IntervalDataName(IntervalData::kMidwallContours),
            "midwall contours");
  EXPECT_EQ(IntervalDataName(IntervalData::kEpiContours),
            "epicardial contours");
}

}  // namespace
}  // namespace pfdm
