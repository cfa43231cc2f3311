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

// The analysis keeps the labels, and a shifted slice warns in the frames
// where it is off, beside the fit's own reasons.
TEST(SegmentationSourceTest, AttachKeepsTheLabelsAndWarnsOfAShiftedSlice) {
  MaskPhantomOptions options;
  options.num_frames = 2;
  options.shifted_slice = 5;
  options.shift_voxels = 4;
  const MaskPhantom mask = MakeMaskPhantom(options);
  const std::string file = ScratchDirectory("attach") + "/mask.nii.gz";
  WriteLabelVolume(mask.volume, file);
  const Segmentation s = ReadSegmentation(file, "lv=3,myo=2,rv=1");
  FitAnalysis analysis;
  analysis.verdicts.resize(2);
  analysis.verdicts[1].Warn("rms_size", "kept");
  AttachSegmentation(s, &analysis);
  ASSERT_TRUE(analysis.segmentation.has_value());
  EXPECT_EQ(analysis.segmentation->source, file);
  EXPECT_EQ(analysis.segmentation->labels.rv, 1);
  EXPECT_EQ(analysis.segmentation->frames, 2);
  for (int t = 0; t < 2; ++t) {
    EXPECT_TRUE(analysis.verdicts[t].Has("misaligned_slice")) << t;
  }
  EXPECT_TRUE(analysis.verdicts[1].Has("rms_size"));
  EXPECT_NE(analysis.verdicts[0].Summary().find("slice 5"), std::string::npos)
      << analysis.verdicts[0].Summary();
}

}  // namespace
}  // namespace pfdm
