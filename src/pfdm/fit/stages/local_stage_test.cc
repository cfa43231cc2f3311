#include "pfdm/fit/stages/local_stage.h"

#include "gtest/gtest.h"
#include "pfdm/fit/stages/frame_fit.h"
#include "pfdm/fit/stages/frame_summary.h"
#include "pfdm/fit/stages/start.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// The local field on top of frame 0's global fit takes up what the global
// functions leave: the residual falls, most for tags (which pull with their
// whole vector), and contours settle in a few rounds.
TEST(LocalStageTest, TakesUpWhatTheGlobalFitLeaves) {
  for (const bool contours : {false, true}) {
    PointSequence sequence = MakeTestPhantom(1000, 2).points;
    if (contours) {
      for (Frame& frame : sequence.frames) {
        for (DataPoint& p : frame.points) p.id += 1000000 * frame.index;
      }
    }
    FitOptions options;
    options.local.enabled = false;
    SequenceStart start =
        StartSequence(sequence, ModelConfig::Paper(17), options);
    CarriedState carried(start.model);
    FrameFit global = FitFrame(sequence.frames[0], true, start.frames_per_id,
                               options, sequence.source, &start.wall, &carried);
    std::vector<MaterialPoint> material;
    const FramePoints points = MakeFramePoints(
        sequence.frames[0], true, start.frames_per_id, {}, &material);
    options.local.enabled = true;
    FrameFit local = global;
    Model model = carried.model;
    FitLocalStage(points, options, sequence.source, &model, &local);
    Summarize(model, points.positions, &local);
    EXPECT_FALSE(model.state.local.values.empty()) << contours;
    EXPECT_GT(local.local_iterations, 0) << contours;
    EXPECT_LT(local.rms_mm, 0.97 * global.rms_mm) << contours;
  }
}

// Contours slide; tags, tracked or on their first frame, do not.
TEST(LocalStageTest, OnlyContoursSlide) {
  FramePoints frame;
  frame.positions.resize(4);
  frame.is_tag = {true, false, false, true};
  frame.untracked = {0, 1, 2};  // A tag's first frame, two contour points.
  frame.tracked = {3};
  EXPECT_EQ(LocalSlidingPoints(frame),
            std::vector<bool>({false, true, true, false}));
}

}  // namespace
}  // namespace pfdm
