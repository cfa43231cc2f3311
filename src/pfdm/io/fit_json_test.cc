#include "pfdm/io/fit_json.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/model/model_surface.h"
#include "pfdm/testing/small_phantom_fit.h"

namespace pfdm {
namespace {

TEST(FitJsonTest, HasVolumesEjectionFractionAndRegions) {
  const FittedPhantom& f = SmallPhantomFit();
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, f.fit, FitOptions()));
  ASSERT_EQ(json["frames"].size(), 3u);
  std::vector<double> volumes;
  for (const auto& frame : json["frames"]) {
    volumes.push_back(frame["midwall_volume_ml"].get<double>());
    EXPECT_FALSE(frame.contains("cavity_volume_ml"));
    // Tags: frame 0's rounds settle, later frames search nothing.
    EXPECT_EQ(frame["correspondence_unsettled_mm"].get<double>(), 0.0);
  }
  // Tags on one surface: named what it is, no ejection fraction.
  EXPECT_EQ(json["model"]["wall"], "midwall");
  EXPECT_EQ(json["model"]["volume_surface"], "midwall");
  EXPECT_FALSE(json.contains("ejection_fraction"));
  // How the axis was found, and whether the data reach the apex.
  EXPECT_EQ(json["model"]["axis_source"], f.fit.axis_source);
  EXPECT_EQ(json["model"]["axis_source"].get<std::string>().rfind(
                "point cloud, best of ", 0),
            0u);
  EXPECT_EQ(json["model"]["apex_in_data"], true);
  EXPECT_EQ(json["model"]["apex_data_distance_fraction"].get<double>(),
            f.fit.apex_data_distance);
  EXPECT_LT(json["model"]["lowest_data_height_fraction"].get<double>(), 0.05);
  EXPECT_EQ(json["model"]["lowest_data_u"].get<double>(), f.fit.lowest_data_u);
  // The fitted surface's volume within 2 % of the true model's.
  for (int t = 0; t < 3; ++t) {
    const double truth = CavityVolumeMl(f.phantom.truth[t]);
    EXPECT_NEAR(volumes[t], truth, 0.02 * truth) << t;
  }
  const auto& ef = json["midwall_volume_fraction"];
  EXPECT_NE(ef["definition"].get<std::string>().find("not the ejection"),
            std::string::npos);
  EXPECT_EQ(ef["ed_frame"], 0);
  EXPECT_EQ(ef["es_frame"], 2);
  EXPECT_EQ(ef["es_by_midwall"], false);
  EXPECT_DOUBLE_EQ(ef["edv_ml"].get<double>(), volumes[0]);
  EXPECT_NEAR(ef["ratio"].get<double>(), 1.0 - volumes[2] / volumes[0], 1e-12);
  EXPECT_NE(ef["cavity_closure"].get<std::string>().find("flat lid"),
            std::string::npos);
  ASSERT_EQ(json["regions"].size(), 17u);
  EXPECT_EQ(json["regions"][0]["name"], "basal 1");
  EXPECT_EQ(json["regions"][16]["name"], "apex");
  EXPECT_EQ(json["regions"][16]["segment"], 17);
  // No RV insertion: the segments say they are not anatomical, and why.
  EXPECT_EQ(json["segments_anatomical"], false);
  EXPECT_EQ(json["segments"]["anchor"], "no RV insertion given");
  EXPECT_NE(
      json["segments"]["definition"].get<std::string>().find("not anatomical"),
      std::string::npos);
  EXPECT_FALSE(json["segments"].contains("rv_insertion"));
  EXPECT_EQ(json["segments"]["apex_cap"]["measured"],
            json["model"]["apex_in_data"]);
  EXPECT_EQ(json["regions"][15]["rotation_deg"].size(), 3u);
  EXPECT_EQ(json["regions"][15]["rotation_deg"][0].get<double>(), 0.0);
  EXPECT_LT(json["regions"][15]["rotation_deg"][2].get<double>(), -1.0);
  EXPECT_EQ(json["settings"]["points"], f.phantom.points.source);
  EXPECT_FALSE(json["settings"].contains("contour_types"));
}

// Anchored to an RV insertion: AHA names, the insertion's longitudes and
// sense; without data near the apex segment 17's numbers are null.
TEST(FitJsonTest, AnatomicalSegmentsAndAnApexCapNotSeen) {
  const FittedPhantom& f = SmallPhantomFit();
  SequenceFit fit = f.fit;
  fit.apex_in_data = false;
  RegionLayout layout;
  layout.anatomical = true;
  layout.anchor = "--rv_insertion";
  layout.anchor_v = 0.5;
  layout.direction = -1.0;
  layout.inferior_v = 0.5 - 2.0;
  layout.anterior_points = layout.inferior_points = 1;
  const nlohmann::json json = nlohmann::json::parse(FitJson(
      f.phantom.points, fit, FitOptions(), AnalyzeFit(fit, {}, layout)));
  EXPECT_EQ(json["segments_anatomical"], true);
  const auto& segments = json["segments"];
  EXPECT_EQ(segments["anchor"], "--rv_insertion");
  EXPECT_NE(segments["definition"].get<std::string>().find("Cerqueira"),
            std::string::npos);
  EXPECT_NEAR(segments["rv_insertion"]["anterior_v_deg"].get<double>(),
              0.5 * 180 / 3.14159265358979323846, 1e-9);
  EXPECT_NEAR(segments["rv_insertion"]["septal_arc_deg"].get<double>(),
              2.0 * 180 / 3.14159265358979323846, 1e-9);
  EXPECT_EQ(segments["apex_cap"]["measured"], false);
  EXPECT_EQ(json["regions"][1]["name"], "basal anteroseptal");
  EXPECT_EQ(json["regions"][13]["name"], "apical septal");
  const auto& cap = json["regions"][16];
  EXPECT_EQ(cap["name"], "apex");
  EXPECT_TRUE(cap["radial_contraction_percent"][2].is_null());
  EXPECT_TRUE(cap["peak_ecc_percent"].is_null());
  EXPECT_GT(cap["area_mm2"].get<double>(), 10.0);
  EXPECT_TRUE(json["regions"][15]["ecc_percent"][2].is_number());
}

// Strain per frame in the clinical block, per region and level, peaks in
// the strain block: the model's phantom contracts, so the peaks are
// negative, at a later frame, and frame 0 strains nothing.
TEST(FitJsonTest, HasStrainPerFrameRegionAndPeaks) {
  const FittedPhantom& f = SmallPhantomFit();
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, f.fit, FitOptions()));
  double least_gcs = 0.0, least_gls = 0.0;
  for (const auto& frame : json["frames"]) {
    least_gcs =
        std::min(least_gcs, frame["clinical"]["gcs_percent"].get<double>());
    least_gls =
        std::min(least_gls, frame["clinical"]["gls_percent"].get<double>());
  }
  EXPECT_NEAR(json["frames"][0]["clinical"]["gcs_percent"].get<double>(), 0.0,
              1e-9);
  const auto& strain = json["strain"];
  EXPECT_EQ(strain["peak_gcs_percent"].get<double>(), least_gcs);
  EXPECT_EQ(strain["peak_gls_percent"].get<double>(), least_gls);
  EXPECT_LT(least_gcs, -3.0);
  EXPECT_GT(strain["peak_gcs_frame"].get<int>(), 0);
  EXPECT_EQ(strain["levels"]["mid"]["ecc_percent"].size(), 3u);
  const auto& region = json["regions"][7];
  ASSERT_EQ(region["ecc_percent"].size(), 3u);
  EXPECT_NEAR(region["ecc_percent"][0].get<double>(), 0.0, 1e-9);
  EXPECT_LE(region["peak_ecc_percent"].get<double>(),
            region["ecc_percent"][2].get<double>());
  EXPECT_GT(region["area_mm2"].get<double>(), 100.0);
}

// Each segment's time to peak Ecc is its most negative Ecc's frame (no
// times: in frames from ED), and the index their sample SD over 1-16.
TEST(FitJsonTest, DyssynchronyFromTheSegmentsPeaks) {
  const FittedPhantom& f = SmallPhantomFit();
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, f.fit, FitOptions()));
  const auto& d = json["dyssynchrony"];
  EXPECT_EQ(d["unit"], "frames");
  ASSERT_EQ(d["time_to_peak"].size(), 17u);
  std::vector<double> counted;
  for (int r = 0; r < 17; ++r) {
    const auto& ecc = json["regions"][r]["ecc_percent"];
    if (d["time_to_peak"][r].is_null()) continue;
    const auto least = std::min_element(ecc.begin(), ecc.end());
    EXPECT_EQ(d["peak_frame"][r].get<int>(), least - ecc.begin()) << r;
    EXPECT_EQ(d["time_to_peak"][r].get<double>(), least - ecc.begin()) << r;
    if (r < 16) counted.push_back(d["time_to_peak"][r].get<double>());
  }
  ASSERT_EQ(d["segments"].get<int>(), static_cast<int>(counted.size()));
  ASSERT_GE(counted.size(), 12u);
  double mean = 0.0, squares = 0.0;
  for (double t : counted) mean += t / counted.size();
  for (double t : counted) squares += (t - mean) * (t - mean);
  EXPECT_NEAR(d["index"].get<double>(),
              std::sqrt(squares / (counted.size() - 1)), 1e-12);
  // A uniform phantom's contraction: every segment peaks at ES, frame 2.
  EXPECT_NEAR(mean, 2.0, 1e-12);
}

// What a frame without tracked points cannot show is null, and fit.json
// lists those frames; the other frames and numbers are as measured.  Tags
// everywhere: numbers, and no list.
TEST(FitJsonTest, WhatIsNotMeasuredIsNull) {
  const FittedPhantom& f = SmallPhantomFit();
  const nlohmann::json tags =
      nlohmann::json::parse(FitJson(f.phantom.points, f.fit, FitOptions()));
  EXPECT_FALSE(tags.contains("not_measured"));
  SequenceFit fit = f.fit;
  fit.frames[2].tracked = false;
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(f.phantom.points, fit, FitOptions()));
  EXPECT_EQ(json["not_measured"]["frames"], nlohmann::json({2}));
  EXPECT_NE(json["not_measured"]["definition"].get<std::string>().find(
                "tracked points"),
            std::string::npos);
  const auto& measured = json["frames"][1]["clinical"];
  const auto& held = json["frames"][2]["clinical"];
  for (const char* key :
       {"net_twist_deg", "apex_rotation_deg", "base_rotation_deg",
        "torsion_deg_per_cm", "shear_angle_deg", "gcl_percent"}) {
    EXPECT_TRUE(measured[key].is_number()) << key;
    EXPECT_TRUE(held[key].is_null()) << key;
    EXPECT_TRUE(tags["frames"][2]["clinical"][key].is_number()) << key;
  }
  EXPECT_EQ(held["radial_contraction_percent"],
            tags["frames"][2]["clinical"]["radial_contraction_percent"]);
  EXPECT_GT(held["radial_contraction_percent"].get<double>(), 5.0);
  EXPECT_TRUE(held["gcs_percent"].is_number());
  for (const auto& region : json["regions"]) {
    EXPECT_TRUE(region["rotation_deg"][1].is_number());
    EXPECT_TRUE(region["rotation_deg"][2].is_null());
    EXPECT_TRUE(region["ecl_percent"][2].is_null());
    EXPECT_TRUE(region["ecc_percent"][2].is_number());
  }
  EXPECT_LT(tags["regions"][15]["rotation_deg"][2].get<double>(), -1.0);
  EXPECT_EQ(json["regions"][15]["rotation_deg"][1],
            tags["regions"][15]["rotation_deg"][1]);
}

// The wall time outside the frames' solve_seconds: the start (the long
// axis) and the checks after the frames, as the fit measured them.
TEST(FitJsonTest, TimesTheStartAndTheChecks) {
  const FittedPhantom& f = SmallPhantomFit();
  SequenceFit fit = f.fit;
  fit.start_seconds = 0.125;
  fit.checks_seconds = 0.5;
  const nlohmann::json timing = nlohmann::json::parse(
      FitJson(f.phantom.points, fit, FitOptions()))["timing"];
  EXPECT_EQ(timing["start_seconds"].get<double>(), 0.125);
  EXPECT_EQ(timing["checks_seconds"].get<double>(), 0.5);
  EXPECT_EQ(timing.size(), 2u);
}

// The loss in the settings: none as before (the scale as given, no
// loss_scale); auto with each frame's measured scale; a number as given.
TEST(FitJsonTest, RecordsTheLossScaleUsed) {
  const FittedPhantom& f = SmallPhantomFit();
  SequenceFit fit = f.fit;
  for (int t = 0; t < 3; ++t) fit.frames[t].loss_scale_mm = 0.5 + t;
  FitOptions options;
  nlohmann::json settings = nlohmann::json::parse(
      FitJson(f.phantom.points, fit, options))["settings"];
  EXPECT_EQ(settings["loss"], "none");
  EXPECT_FALSE(settings.contains("loss_scale"));
  EXPECT_EQ(settings["loss_scale_mm"].get<double>(), 1.0);
  options.loss = "cauchy";
  settings = nlohmann::json::parse(
      FitJson(f.phantom.points, fit, options))["settings"];
  EXPECT_EQ(settings["loss_scale"], "auto");
  EXPECT_EQ(settings["loss_scale_mm"], nlohmann::json({0.5, 1.5, 2.5}));
  options.loss_scale_auto = false;
  options.loss_scale_mm = 2.0;
  settings = nlohmann::json::parse(
      FitJson(f.phantom.points, fit, options))["settings"];
  EXPECT_EQ(settings["loss_scale"].get<double>(), 2.0);
  EXPECT_EQ(settings["loss_scale_mm"].get<double>(), 2.0);
}

// Guide points name the contour types they kept, so a fit can be redone.
TEST(FitJsonTest, NamesTheContourTypesKept) {
  const FittedPhantom& f = SmallPhantomFit();
  PointSequence points = f.phantom.points;
  points.contour_types = {"SAX_LV_ENDOCARDIAL", "AORTA_VALVE"};
  const nlohmann::json json =
      nlohmann::json::parse(FitJson(points, f.fit, FitOptions()));
  EXPECT_EQ(json["settings"]["contour_types"],
            nlohmann::json({"SAX_LV_ENDOCARDIAL", "AORTA_VALVE"}));
}

}  // namespace
}  // namespace pfdm
