#include "pfdm/io/segmentation_json.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(SegmentationJsonTest, NamesTheLabelsAndTheMisalignedSlices) {
  SegmentationRecord r;
  r.source = "patient001/";
  r.labels = {3, 2, 1};
  r.slices = 10;
  r.frames = 2;
  r.voxel_mm = {1.5625, 1.5625, 10.0};
  r.geometry = "sform";
  r.apex_slice = 9;
  r.base_slice = {1, 2};
  r.slices_fitted = {9, 8};
  r.rv_insertion_slices = 6;
  r.misaligned = {{4, {0, 1}, 5.25}};
  const nlohmann::ordered_json j = SegmentationJson(r);
  EXPECT_EQ(j["source"], "patient001/");
  EXPECT_EQ(j["labels"]["lv"], 3);
  EXPECT_EQ(j["labels"]["myo"], 2);
  EXPECT_EQ(j["labels"]["rv"], 1);
  EXPECT_EQ(j["voxel_mm"][2], 10.0);
  EXPECT_EQ(j["base_slice"][1], 2);
  EXPECT_EQ(j["slices_fitted"][0], 9);
  EXPECT_EQ(j["rv_insertion_slices"], 6);
  ASSERT_EQ(j["misaligned"].size(), 1u);
  EXPECT_EQ(j["misaligned"][0]["slice"], 4);
  EXPECT_EQ(j["misaligned"][0]["frames"][1], 1);
  EXPECT_EQ(j["misaligned"][0]["max_offset_mm"], 5.25);
  r.labels.rv = -1;
  EXPECT_TRUE(SegmentationJson(r)["labels"]["rv"].is_null());
}

}  // namespace
}  // namespace pfdm
