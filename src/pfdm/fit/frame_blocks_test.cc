#include "pfdm/fit/frame_blocks.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

TEST(FrameBlocksTest, ReferenceFrameVariesThePoseAndTheGaugeFreeEntries) {
  Model model = TestSpheroid(5);
  ceres::Problem problem;
  FrameBlocks blocks(FrameKind::kReference, &model, &problem);
  EXPECT_FALSE(problem.IsParameterBlockConstant(model.state.center.data()));
  EXPECT_EQ(blocks.entries(kGlobalsBlock), nullptr);  // a0 is held.
  ASSERT_NE(blocks.entries(2), nullptr);
  // a1, a2, e1o, e2o: the rest are held on frame 0 (gauge.h).
  EXPECT_EQ(blocks.entries(2)->size(), 4);
  EXPECT_EQ(blocks.entries(2)->IndexOf(kTau), -1);
  // The pose, the globals and five knots.
  EXPECT_EQ(problem.NumParameterBlocks(), 2 + 1 + 5);
}

TEST(FrameBlocksTest, TrackedFrameVariesThePoseAndStoresItsEntries) {
  Model model = TestSpheroid(5);
  ceres::Problem problem;
  FrameBlocks blocks(FrameKind::kTracked, &model, &problem);
  // Translation and tilt live in the pose (its spin is a gauge residual).
  EXPECT_FALSE(problem.IsParameterBlockConstant(model.state.center.data()));
  EXPECT_FALSE(problem.IsParameterBlockConstant(model.state.quaternion.data()));
  const FreeEntries* knot = blocks.entries(1);
  ASSERT_NE(knot, nullptr);
  const int tau = knot->IndexOf(kTau);
  ASSERT_GE(tau, 0);
  const_cast<FreeEntries*>(knot)->parameters()[tau] = 0.25;
  EXPECT_EQ(model.state.knots[1][kTau], 0.0);
  blocks.Store();
  EXPECT_EQ(model.state.knots[1][kTau], 0.25);
  int free_blocks = 0;
  blocks.ForEachFree([&](double*, const std::vector<int>&) { ++free_blocks; });
  EXPECT_EQ(free_blocks, 5);
}

}  // namespace
}  // namespace pfdm
