// Fits to the real third-party LV data in ../shared/data; skipped without it.
#include "gtest/gtest.h"
#include "pfdm/fitter.h"
#include "pfdm/point_reader.h"
#include "test_util.h"

namespace pfdm {
namespace {

// biv-me patient 1: SAX and LAX endocardial contours of 25 frames, no
// correspondence between frames.  The paper's model fits each frame to
// within 2 mm RMS.
TEST(RealDataTest, BivMePatientContoursFitWithinTwoMillimetres) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const PointSequence points = ReadGpFiles(
      shared + "/biv-me-patient1/guidepoints", ExpandContourAlias("lv-endo"));
  const SequenceFit fit =
      FitSequence(points, ModelConfig::Paper(17), FitOptions());
  ASSERT_EQ(fit.frames.size(), 25u);
  for (const FrameFit& frame : fit.frames) {
    EXPECT_LT(frame.rms_mm, 2.0) << "frame " << frame.frame;
    EXPECT_GT(frame.rms_mm, 0.3) << "frame " << frame.frame;  // Not degenerate.
  }
}

}  // namespace
}  // namespace pfdm
