// pfdm fit --segmentation end to end: the independent LV phantom voxelized
// at clinical resolution (testing/mask_phantom.h), its contours fitted as a
// solid, the volumes against the voxels counted.
#include <cstdio>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/nifti_writer.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/rv_insertion.h"
#include "pfdm/segmentation/mask_contours.h"
#include "pfdm/testing/mask_phantom.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

struct MaskFit {
  MaskPhantom mask;
  MaskContours contours;
  SequenceFit fit;
  FitAnalysis analysis;
};

MaskFit FitMask(const MaskPhantomOptions& options) {
  MaskFit f{MakeMaskPhantom(options), {}, {}, {}};
  f.contours = ExtractMaskContours(f.mask.volume, options.labels);
  f.fit = FitSequence(f.contours.points, ModelConfig::Paper(17), FitOptions());
  RvInsertion insertion;
  insertion.unlabelled = f.contours.rv_insertion;
  f.analysis =
      AnalyzeFit(f.fit, {}, AnatomicalLayout(f.fit.ModelAt(0), insertion));
  return f;
}

double Ef(double ed, double es) { return (ed - es) / ed; }

// 1.5 mm in-plane, 8 mm slices, 10 frames of systole: the fitted cavity's
// volumes and ejection fraction within 5 % of the voxels counted, the mass
// within 10 %, and the segments anatomical.
TEST(SegmentationFitTest, PhantomMaskVolumes) {
  MaskPhantomOptions options;
  options.num_frames = 10;
  const MaskFit f = FitMask(options);
  ASSERT_TRUE(f.fit.config.Solid());
  const int last = static_cast<int>(f.fit.frames.size()) - 1;
  for (int t = 0; t <= last; ++t) {
    const ClinicalSummary& c = f.analysis.clinical[t];
    std::printf(
        "frame %d: rms %.2f mm; cavity fit %.1f voxels %.1f truth %.1f ml; "
        "myocardium fit %.1f voxels %.1f truth %.1f ml\n",
        t, f.fit.frames[t].rms_mm, c.volume_ml, f.mask.cavity_ml[t],
        f.mask.phantom.truth[t].endo_volume_ml, c.myocardial_volume_ml,
        f.mask.myocardium_ml[t], f.mask.phantom.truth[t].myocardial_volume_ml);
    EXPECT_NEAR(c.volume_ml, f.mask.cavity_ml[t], 0.05 * f.mask.cavity_ml[t]);
    EXPECT_NEAR(c.lv_mass_g, 1.05 * f.mask.myocardium_ml[t],
                0.10 * 1.05 * f.mask.myocardium_ml[t]);
    EXPECT_LT(f.fit.frames[t].rms_mm, 1.0);
  }
  const double voxel_ef = Ef(f.mask.cavity_ml[0], f.mask.cavity_ml[last]);
  std::printf("EF fit %.3f voxels %.3f\n", f.analysis.ejection_fraction.ratio,
              voxel_ef);
  EXPECT_NEAR(f.analysis.ejection_fraction.ratio, voxel_ef, 0.05 * voxel_ef);
  EXPECT_TRUE(f.analysis.layout.anatomical) << f.analysis.layout.anchor;
}

// The CLI on the mask written as a 4D NIfTI with one slice shifted 6 mm:
// the fit is written and the slice named on stderr.
TEST(SegmentationFitTest, CliFitsAFileAndNamesAShiftedSlice) {
  MaskPhantomOptions options;
  options.num_frames = 2;
  options.shifted_slice = 5;
  options.shift_voxels = 4;
  const MaskPhantom mask = MakeMaskPhantom(options);
  const std::string dir = ScratchDirectory("cli");
  WriteLabelVolume(mask.volume, dir + "/mask.nii.gz");
  const CommandResult r = RunPfdm("fit --segmentation " + dir +
                                  "/mask.nii.gz --labels lv=3,myo=2,rv=1 "
                                  "--out " +
                                  dir + "/fit");
  EXPECT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NE(r.output.find("segmentation: 14 slices x 2 frames"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.error.find("warning: " + dir +
                         "/mask.nii.gz: slice 5: the "
                         "LV cavity's centre lies up to"),
            std::string::npos)
      << r.error;
  EXPECT_NE(r.output.find("segments: AHA, anatomical"), std::string::npos);
  const nlohmann::json json =
      nlohmann::json::parse(ReadText(dir + "/fit/fit.json"));
  EXPECT_EQ(json["settings"]["contour_types"][1], "SAX_LV_EPICARDIAL");
  // The labels read, and the shifted slice in the record and in both
  // frames' verdicts.
  EXPECT_EQ(json["segmentation"]["labels"]["lv"], 3);
  EXPECT_EQ(json["segmentation"]["labels"]["rv"], 1);
  ASSERT_EQ(json["segmentation"]["misaligned"].size(), 1u);
  EXPECT_EQ(json["segmentation"]["misaligned"][0]["slice"], 5);
  EXPECT_NEAR(json["segmentation"]["misaligned"][0]["max_offset_mm"], 6.0, 1.0);
  for (int t = 0; t < 2; ++t) {
    const std::string reasons = json["frames"][t]["quality_reasons"].dump();
    EXPECT_NE(reasons.find("misaligned_slice"), std::string::npos) << reasons;
  }
  // The mask's slices with the fitted walls: 3 slices at ED and ES, in
  // slices.svg and the report.
  const std::string slices = ReadText(dir + "/fit/slices.svg");
  EXPECT_EQ(CountOf(slices, "<text"), 6);
  EXPECT_GT(CountOf(slices, "fill=\"yellow\""), 300);
  EXPECT_NE(ReadText(dir + "/fit/report.html")
                .find("<h2>The segmentation and the fit</h2>"),
            std::string::npos);
}

TEST(SegmentationFitTest, CliBadInputOneLine) {
  const std::string dir = ScratchDirectory("bad");
  WriteText(dir + "/junk.nii", "junk\n");
  CommandResult r =
      RunPfdm("fit --segmentation " + dir + "/junk.nii --out " + dir + "/fit");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.error,
            "pfdm: error: " + dir + "/junk.nii: not a readable NIfTI file\n");
  r = RunPfdm("fit --segmentation " + dir + "/junk.nii --labels lv=1 --out " +
              dir + "/fit");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(CountOf(r.error, "\n"), 1);
  EXPECT_NE(r.error.find("--labels 'lv=1'"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
