#include "pfdm/fit/stages/frame_uncertainty.h"

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {
namespace {

SequenceFit FitTwoFrames(bool uncertainty) {
  PhantomOptions phantom;
  phantom.num_frames = 2;
  phantom.num_points = 400;
  phantom.num_knots = 9;
  FitOptions options;
  options.uncertainty = uncertainty;
  return FitSequence(MakePhantom(phantom).points, ModelConfig::Paper(9),
                     options);
}

// Frame 0 holds tau (the reference has no twist) and a3: sd 0; the tracked
// frame fits both.  Nothing undetermined; sigma near the phantom's 0.5 mm
// noise on frame 0 (only its normal part is left: closest points), larger
// on the tracked frame, whose material points carry frame 0's tangential
// noise (sqrt(5) 0.5 = 1.1 mm at most).
TEST(FrameUncertaintyTest, EveryFrameGetsItsCovariance) {
  const SequenceFit fit = FitTwoFrames(true);
  for (const FrameFit& frame : fit.frames) {
    ASSERT_TRUE(frame.covariance.computed) << frame.frame;
    EXPECT_EQ(frame.covariance.rank_deficiency, 0) << frame.frame;
    EXPECT_EQ(frame.covariance.covariance.rows(),
              static_cast<int>(frame.covariance.entries.size()));
  }
  const FrameCovariance& first = fit.frames[0].covariance;
  const FrameCovariance& second = fit.frames[1].covariance;
  EXPECT_NEAR(first.sigma_mm, 0.5, 0.05);
  EXPECT_GT(second.sigma_mm, 0.5);
  EXPECT_LT(second.sigma_mm, 1.12);
  EXPECT_EQ(first.KnotSd(fit.config, kTau, 4), 0.0);
  EXPECT_EQ(first.KnotSd(fit.config, kA3, 4), 0.0);
  EXPECT_GT(first.KnotSd(fit.config, kA1, 4), 0.0);
  // tau at mid-ventricle: a few tenths of a degree from 400 tags.
  EXPECT_GT(second.KnotSd(fit.config, kTau, 4), 1e-4);
  EXPECT_LT(second.KnotSd(fit.config, kTau, 4), 1e-2);
}

TEST(FrameUncertaintyTest, OffLeavesItOut) {
  const SequenceFit fit = FitTwoFrames(false);
  for (const FrameFit& frame : fit.frames) {
    EXPECT_FALSE(frame.covariance.computed);
  }
}

}  // namespace
}  // namespace pfdm
