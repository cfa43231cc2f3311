#include "pfdm/segmentation/segmentation_record.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(SegmentationRecordTest, KeepsTheLabelsTheGeometryAndTheSlicesFitted) {
  LabelVolume volume;
  volume.source = "mask.nii.gz";
  volume.nx = volume.ny = 4;
  volume.nz = 3;
  volume.nt = 2;
  volume.world_from_voxel.diagonal() << 1.25, 1.25, 8.0, 1.0;
  volume.geometry = "qform";
  MaskContours contours;
  contours.apex_slice = 2;
  contours.base_slice = {0, 1};
  for (int t = 0; t < 2; ++t) {
    for (int k = 0; k < 3; ++k) {
      SliceRing ring;
      ring.frame = t;
      ring.slice = k;
      ring.kept = k >= t;  // Frame 1's base one slice lower.
      contours.rings.push_back(ring);
    }
  }
  contours.rv_insertion.assign(4, Eigen::Vector3d::Zero());
  contours.misaligned = {{1, {0, 1}, 4.5}};
  LabelMap labels{1, 2, -1};
  const SegmentationRecord r = RecordSegmentation(volume, labels, contours);
  EXPECT_EQ(r.source, "mask.nii.gz");
  EXPECT_EQ(r.labels.lv, 1);
  EXPECT_EQ(r.labels.rv, -1);
  EXPECT_EQ(r.slices, 3);
  EXPECT_EQ(r.frames, 2);
  EXPECT_DOUBLE_EQ(r.voxel_mm.x(), 1.25);
  EXPECT_DOUBLE_EQ(r.voxel_mm.z(), 8.0);
  EXPECT_EQ(r.geometry, "qform");
  EXPECT_EQ(r.slices_fitted, (std::vector<int>{3, 2}));
  EXPECT_EQ(r.base_slice, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.rv_insertion_slices, 2);
  ASSERT_EQ(r.misaligned.size(), 1u);
  EXPECT_DOUBLE_EQ(r.misaligned[0].max_offset_mm, 4.5);
}

TEST(SegmentationRecordTest, AMisalignedSliceWarnsInTheFramesItIsOff) {
  const std::vector<Verdict> verdicts =
      SliceAlignmentVerdicts({{5, {1, 3}, 6.04}, {7, {3}, 3.5}}, 4);
  ASSERT_EQ(verdicts.size(), 4u);
  EXPECT_EQ(verdicts[0].quality(), Quality::kOk);
  EXPECT_EQ(verdicts[2].quality(), Quality::kOk);
  ASSERT_EQ(verdicts[1].reasons().size(), 1u);
  EXPECT_EQ(verdicts[1].quality(), Quality::kWarning);
  EXPECT_EQ(verdicts[1].reasons()[0].code, "misaligned_slice");
  EXPECT_EQ(verdicts[1].reasons()[0].text,
            "slice 5 of the segmentation lay off its neighbours' line (up "
            "to 6.0 mm; a breath-hold shift?) and was moved back onto it");
  EXPECT_EQ(verdicts[3].reasons().size(), 2u);
  // A frame outside the sequence is ignored, not a crash.
  EXPECT_EQ(SliceAlignmentVerdicts({{2, {9}, 4.0}}, 4)[3].quality(),
            Quality::kOk);
}

}  // namespace
}  // namespace pfdm
