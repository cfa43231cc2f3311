#include "pfdm/fit/problem/frame_blocks.h"

#include "ceres/autodiff_cost_function.h"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// r = x[0] - 1 over a block of the functions.
struct Offset {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] - T(1.0);
    return true;
  }
};

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

// A solid's thickness h is kept from below 0 (walls that cross), a1..a3
// and the exponents within their ranges; a mid-wall surface has no h.
TEST(FrameBlocksTest, ASolidsThicknessHasTheFloorZero) {
  Model model = TestSpheroid(5);
  model.config.MakeSolid();
  ceres::Problem problem;
  FrameBlocks blocks(FrameKind::kTracked, &model, &problem);
  const FreeEntries* knot = blocks.entries(4);
  ASSERT_NE(knot, nullptr);
  double* parameters = const_cast<double*>(blocks.parameters(4));
  const int h = knot->IndexOf(kH);
  ASSERT_GE(h, 0);
  EXPECT_EQ(problem.GetParameterLowerBound(parameters, h), 0.0);
  EXPECT_GT(problem.GetParameterUpperBound(parameters, h), 1e300);
  const int a1 = knot->IndexOf(kA1);
  ASSERT_GE(a1, 0);
  EXPECT_EQ(problem.GetParameterLowerBound(parameters, a1), 1e-3);
  EXPECT_EQ(problem.GetParameterUpperBound(parameters, a1), 1.0);

  Model surface = TestSpheroid(5);
  ceres::Problem surface_problem;
  FrameBlocks surface_blocks(FrameKind::kTracked, &surface, &surface_problem);
  EXPECT_EQ(surface_blocks.entries(4)->IndexOf(kH), -1);
}

// A cost over the held globals alone is a constant and is not added; one
// over a knot's free entries is.
TEST(FrameBlocksTest, ACostOverConstantBlocksOnlyIsNotAdded) {
  Model model = TestSpheroid(5);
  ceres::Problem problem;
  FrameBlocks blocks(FrameKind::kReference, &model, &problem);
  ASSERT_EQ(blocks.entries(kGlobalsBlock), nullptr);
  auto* constant =
      new ceres::AutoDiffCostFunction<Offset, 1, kNumFunctions>(new Offset);
  EXPECT_EQ(blocks.AddResidual(constant, nullptr, false, {kGlobalsBlock}),
            nullptr);
  EXPECT_EQ(problem.NumResidualBlocks(), 0);
  auto* free =
      new ceres::AutoDiffCostFunction<Offset, 1, kNumFunctions>(new Offset);
  EXPECT_NE(blocks.AddResidual(free, nullptr, false, {2}), nullptr);
  EXPECT_EQ(problem.NumResidualBlocks(), 1);
}

}  // namespace
}  // namespace pfdm
