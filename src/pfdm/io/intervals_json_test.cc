#include "pfdm/io/intervals_json.h"

#include <cmath>
#include <string>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/io/fit_json.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/testing/small_phantom_fit.h"

namespace pfdm {
namespace {

// The small phantom's analysis with made-up sds: every number's sd 1 but
// frame 2's apex rotation (0.5) and net twist, taken for not measured.
FitAnalysis WithSds() {
  const FittedPhantom& f = SmallPhantomFit();
  FitAnalysis a = AnalyzeFit(f.fit);
  NumberSd& sd = a.sd;
  sd.computed = true;
  sd.clinical = a.clinical;
  sd.region_motion = a.region_motion;
  sd.strain = a.strain;
  for (size_t t = 0; t < a.clinical.size(); ++t) {
    for (double* v : ClinicalFields(&sd.clinical[t])) *v = 1.0;
    for (double* v : StrainFields(&sd.strain[t])) *v = 1.0;
    for (RegionMotion& m : sd.region_motion[t]) {
      for (double* v : RegionFields(&m)) *v = 1.0;
    }
  }
  sd.clinical[2].apex_rotation_deg = 0.5;
  a.clinical[2].net_twist_deg = kNotMeasured;
  sd.ejection_fraction = {0, 2, 1.0, 1.0, 0.01};
  return a;
}

bool Near(const nlohmann::json& interval, double low, double high) {
  return interval.size() == 2 &&
         std::abs(interval[0].get<double>() - low) < 1e-9 &&
         std::abs(interval[1].get<double>() - high) < 1e-9;
}

TEST(IntervalsJsonTest, BesideEveryNumberWithUncertainty) {
  const FittedPhantom& f = SmallPhantomFit();
  const FitAnalysis a = WithSds();
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, f.fit, FitOptions(), a));
  const nlohmann::json& clinical = json["frames"][2]["clinical"];
  const double apex = a.clinical[2].apex_rotation_deg;
  EXPECT_TRUE(Near(clinical["apex_rotation_deg_ci95"], apex - 0.5 * kZ95,
                   apex + 0.5 * kZ95))
      << clinical["apex_rotation_deg_ci95"];
  const double gcs = a.strain[2].gcs_percent;
  EXPECT_TRUE(Near(clinical["gcs_percent_ci95"], gcs - kZ95, gcs + kZ95));
  // A number not measured: null, and so is its interval.
  EXPECT_TRUE(clinical["net_twist_deg"].is_null());
  EXPECT_FALSE(clinical.contains("net_twist_deg_ci95"));
  // The volume, beside its surface-named key.
  const double v = a.clinical[1].volume_ml;
  EXPECT_TRUE(
      Near(json["frames"][1]["midwall_volume_ml_ci95"], v - kZ95, v + kZ95));
  // The volume fraction, and a segment's per-frame list.
  const double ratio = a.ejection_fraction.ratio;
  EXPECT_TRUE(Near(json["midwall_volume_fraction"]["ratio_ci95"],
                   ratio - 0.01 * kZ95, ratio + 0.01 * kZ95));
  const nlohmann::json& ecc = json["regions"][3]["ecc_percent_ci95"];
  ASSERT_EQ(ecc.size(), 3u);
  const double e = a.region_motion[2][3].ecc_percent;
  EXPECT_TRUE(Near(ecc[2], e - kZ95, e + kZ95));
  EXPECT_TRUE(json["regions"][3].contains("peak_ecc_percent_ci95"));
  EXPECT_TRUE(json["strain"].contains("peak_gcs_percent_ci95"));
  EXPECT_EQ(json["strain"]["levels"]["mid"]["ell_percent_ci95"].size(), 3u);
  EXPECT_TRUE(json.contains("uncertainty_definition"));
  ASSERT_TRUE(json.contains("uncertainty_calibrated"));
  EXPECT_EQ(json["uncertainty_calibrated"]["data"], "midwall tags");
  EXPECT_EQ(json["uncertainty_calibrated"]["keys"],
            nlohmann::json(CalibratedIntervalKeys(IntervalData::kMidwallTags)));
  // Keys that are no number with an sd get none.
  EXPECT_FALSE(json["frames"][1].contains("rms_mm_ci95"));
  EXPECT_FALSE(json["regions"][3].contains("area_mm2_ci95"));
}

// Each frame's residual sd, and the data's noise its covariance is
// scaled by: the same but on a solid's tracked frame of tags alone, whose
// sd across the wall it is (fit/problem/directional_noise.h).
TEST(IntervalsJsonTest, FramesSayWhichNoiseScalesTheirCovariance) {
  const FittedPhantom& f = SmallPhantomFit();
  SequenceFit fit = f.fit;
  for (FrameFit& frame : fit.frames) {
    frame.covariance.computed = true;
    frame.covariance.sigma_mm = 0.6;
  }
  fit.frames[1].covariance.normal_sigma_mm = 0.9;
  fit.frames[1].covariance.tangent_sigma_mm = 0.4;
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, fit, FitOptions()));
  const nlohmann::json& first = json["frames"][0]["uncertainty"];
  EXPECT_EQ(first["sigma_mm"], 0.6);
  EXPECT_EQ(first["noise_sigma_mm"], 0.6);
  EXPECT_FALSE(first.contains("normal_sigma_mm"));
  const nlohmann::json& second = json["frames"][1]["uncertainty"];
  EXPECT_EQ(second["sigma_mm"], 0.6);
  EXPECT_EQ(second["noise_sigma_mm"], 0.4);
  EXPECT_EQ(second["normal_sigma_mm"], 0.9);
}

TEST(IntervalsJsonTest, AbsentWithoutUncertainty) {
  const FittedPhantom& f = SmallPhantomFit();
  const std::string text = FitJson(f.phantom.points, f.fit, FitOptions());
  EXPECT_EQ(text.find("_ci95"), std::string::npos);
  EXPECT_EQ(text.find("uncertainty_definition"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
