#include "pfdm/io/segmentation_source.h"

#include "gtest/gtest.h"
#include "pfdm/io/nifti_writer.h"
#include "pfdm/testing/mask_phantom.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// The phantom's mask written as a 4D file with M&Ms' labels and read back:
// the same contours as from memory, and an RV insertion per slice.
TEST(SegmentationSourceTest, FileGivesTheContours) {
  MaskPhantomOptions options;
  options.labels = LabelMap{1, 2, 3};
  const MaskPhantom mask = MakeMaskPhantom(options);
  const std::string file = ScratchDirectory("seg") + "/mask.nii.gz";
  WriteLabelVolume(mask.volume, file);
  const Segmentation s = ReadSegmentation(file, "mnms");
  const MaskContours direct = ExtractMaskContours(mask.volume, options.labels);
  ASSERT_EQ(s.contours.points.frames.size(), 3u);
  ASSERT_EQ(s.contours.points.frames[2].points.size(),
            direct.points.frames[2].points.size());
  EXPECT_LT((s.contours.points.frames[2].points[7].position -
             direct.points.frames[2].points[7].position)
                .norm(),
            1e-4);
  ASSERT_TRUE(s.rv_insertion.has_value());
  EXPECT_EQ(s.rv_insertion->unlabelled.size(), direct.rv_insertion.size());
  EXPECT_NE(s.rv_insertion->source.find("contact"), std::string::npos);
  // ACDC's labels on M&Ms' mask: lv=3 is the RV there, which no myocardium
  // closes in.
  EXPECT_NE(InputErrorOf([&] {
              ReadSegmentation(file, "acdc");
            }).find("no slice where the myocardium"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
