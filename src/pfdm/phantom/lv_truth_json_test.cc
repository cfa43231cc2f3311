#include "pfdm/phantom/lv_truth_json.h"

#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"

namespace pfdm {
namespace {

TEST(LvPhantomJsonTest, WritesEveryFramesTruth) {
  LvPhantomOptions options;
  options.num_tags = 10;
  options.deformation.lesion = true;
  options.outlier_fraction = 0.3;
  const LvPhantom phantom = MakeLvPhantom(options);
  const nlohmann::json json = nlohmann::json::parse(LvTruthJson(phantom));
  EXPECT_EQ(json["phantom"], "lv");
  EXPECT_EQ(json["kinematics"], "systole");
  EXPECT_EQ(json["tags"], "midwall");
  EXPECT_EQ(json["lesion"], true);
  EXPECT_EQ(json["num_frames"], 5);
  EXPECT_EQ(json["ring_heights"].size(), 20u);
  EXPECT_EQ(json["geometry"]["length_mm"], 95.0);
  EXPECT_EQ(json["summary"]["es_frame"], 4);
  EXPECT_NEAR(
      json["summary"]["ejection_fraction"].get<double>(),
      1.0 - phantom.truth[4].endo_volume_ml / phantom.truth[0].endo_volume_ml,
      1e-12);
  ASSERT_EQ(json["frames"].size(), 5u);
  const nlohmann::json& es = json["frames"][4];
  EXPECT_EQ(es["frame"], 4);
  EXPECT_NEAR(es["longitudinal_shortening_percent"].get<double>(), 17.0, 1e-9);
  EXPECT_EQ(es["rigid"]["axial_shift_mm"].get<double>(), 4.0);
  EXPECT_EQ(es["net_twist_deg"].get<double>(), phantom.truth[4].net_twist_deg);
  EXPECT_EQ(es["mean_radial_contraction_percent"].get<double>(),
            phantom.truth[4].mean_radial_contraction_percent);
  for (const char* layer : {"midwall", "endo", "epi"}) {
    EXPECT_EQ(es["rings"][layer]["rotation_deg"].size(), 20u) << layer;
    EXPECT_EQ(es["rings"][layer]["radial_contraction_percent"].size(), 20u);
  }
  EXPECT_EQ(es["rings"]["endo"]["radial_contraction_percent"][9].get<double>(),
            phantom.truth[4].endo.radial_contraction_percent[9]);
  ASSERT_EQ(es["segments"].size(), 16u);
  EXPECT_EQ(es["segments"][7]["name"], "mid 2");
  EXPECT_EQ(es["segments"][7]["radial_contraction_percent"].get<double>(),
            phantom.truth[4].segments[7].radial_contraction_percent);
  EXPECT_EQ(json["outlier_fraction"].get<double>(), 0.3);
  EXPECT_EQ(json["outlier_mm"], nlohmann::json({5.0, 10.0}));
  ASSERT_FALSE(phantom.truth[4].outlier_ids.empty());
  EXPECT_EQ(es["outlier_ids"].get<std::vector<int>>(),
            phantom.truth[4].outlier_ids);
  const nlohmann::json& pose = es["world_from_body"];
  ASSERT_EQ(pose.size(), 4u);
  EXPECT_EQ(pose[3], nlohmann::json({0.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(pose[0][3].get<double>(),
            phantom.truth[4].world_from_body.translation().x());
}

}  // namespace
}  // namespace pfdm
