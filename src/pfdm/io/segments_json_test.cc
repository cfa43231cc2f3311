#include "pfdm/io/segments_json.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Two frames of 17 regions; region 3's frame 1 holds known numbers and its
// endocardial Ell is not measured.
FitAnalysis TwoFramesOfLayers() {
  FitAnalysis analysis;
  analysis.regions = Regions(RegionLayout());
  analysis.region_layers.assign(2, std::vector<RegionLayers>(17));
  RegionLayers& region = analysis.region_layers[1][3];
  region.err_percent = 41.5;
  region.layers[0] = {-24.5, std::nan(""), 12.0};
  region.layers[1] = {-18.0, -15.5, 40.0};
  region.layers[2] = {-6.5, -13.0, 80.0};
  return analysis;
}

TEST(SegmentsJsonTest, LayersPerFrameWithNullWhereNotMeasured) {
  const FitAnalysis analysis = TwoFramesOfLayers();
  const nlohmann::ordered_json layers = RegionLayersJson(analysis, 3);
  ASSERT_TRUE(layers.is_object());
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers.begin().key(), "endocardium");
  EXPECT_EQ(layers["endocardium"]["ecc_percent"][0].get<double>(), 0.0);
  EXPECT_EQ(layers["endocardium"]["ecc_percent"][1].get<double>(), -24.5);
  EXPECT_TRUE(layers["endocardium"]["ell_percent"][1].is_null());
  EXPECT_EQ(layers["midwall"]["thickening_percent"][1].get<double>(), 40.0);
  EXPECT_EQ(layers["epicardium"]["ell_percent"][1].get<double>(), -13.0);
  const nlohmann::ordered_json err = RegionErrJson(analysis, 3);
  ASSERT_EQ(err.size(), 2u);
  EXPECT_EQ(err[1].get<double>(), 41.5);
}

// Without a wall there are no layers: null, not zeros.
TEST(SegmentsJsonTest, NoWallNoLayers) {
  FitAnalysis analysis;
  analysis.regions = Regions(RegionLayout());
  EXPECT_TRUE(RegionLayersJson(analysis, 3).is_null());
  EXPECT_TRUE(RegionErrJson(analysis, 3).is_null());
}

// Where a solid's segments cannot show what moves unlike its ring
// (FitAnalysis::regional_limit), the segments' section says so and what
// to do; elsewhere it has no such key.
TEST(SegmentsJsonTest, SaysWhatTheSegmentsCannotShowThroughTheWall) {
  FitAnalysis analysis;
  analysis.regions = Regions(RegionLayout());
  EXPECT_FALSE(SegmentsSection(analysis).contains("through_the_wall"));
  analysis.regional_limit = RegionalLimit::kRing;
  const nlohmann::ordered_json section = SegmentsSection(analysis);
  ASSERT_TRUE(section.contains("through_the_wall"));
  EXPECT_NE(section["through_the_wall"].get<std::string>().find(
                "--local_transmural on"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
