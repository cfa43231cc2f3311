#include "pfdm/fit/correspondence/measured_depths.h"

#include <vector>

#include "gtest/gtest.h"
#include "pfdm/model/transmural.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

std::vector<MaterialPoint> AtU(double u, size_t n) {
  return std::vector<MaterialPoint>(n, MaterialPoint{u, 0.3, 0.0});
}

// Frame 0's layers are evenly spaced: w = 2 d / h (the shell's wall 10 mm).
TEST(MeasuredDepthsTest, EvenLayersTakeTwiceTheDistanceOverTheThickness) {
  const Model shell = TestShell(9);
  const std::vector<double> depths =
      MeasuredDepths(shell, AtU(0.2, 4), {-5.0, -1.0, 0.0, 4.0});
  EXPECT_DOUBLE_EQ(depths[0], -1.0);
  EXPECT_DOUBLE_EQ(depths[1], -0.2);
  EXPECT_DOUBLE_EQ(depths[2], 0.0);
  EXPECT_DOUBLE_EQ(depths[3], 0.8);
}

// With a shift and a squeeze the depth is the layer whose WallDepth is the
// distance: WallDepth's inverse.
TEST(MeasuredDepthsTest, InvertsTheDepthProfile) {
  Model shell = TestShell(9);
  for (FunctionValues& knot : shell.state.knots) {
    knot[kWallShift] = 0.8;
    knot[kWallSqueeze] = -0.6;
  }
  const FunctionValues f = shell.FunctionsAt(0.2);
  const std::vector<double> truth = {-1.3, -1.0, -0.4, 0.0, 0.55, 1.0, 1.2};
  std::vector<double> distances;
  for (double w : truth) distances.push_back(WallDepth(f.data(), w));
  const std::vector<double> depths =
      MeasuredDepths(shell, AtU(0.2, truth.size()), distances);
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_NEAR(depths[i], truth[i], 1e-10) << i;
  }
}

// An outlier far outside the wall is taken at kMaxMeasuredDepth; a wall of
// no thickness says no depth.
TEST(MeasuredDepthsTest, FarTagsAreClampedAndNoWallGivesZero) {
  Model shell = TestShell(9);
  const std::vector<double> far =
      MeasuredDepths(shell, AtU(0.2, 2), {40.0, -40.0});
  EXPECT_DOUBLE_EQ(far[0], kMaxMeasuredDepth);
  EXPECT_DOUBLE_EQ(far[1], -kMaxMeasuredDepth);
  for (FunctionValues& knot : shell.state.knots) knot[kH] = 0.0;
  EXPECT_DOUBLE_EQ(MeasuredDepths(shell, AtU(0.2, 1), {3.0})[0], 0.0);
}

TEST(MeasuredDepthsTest, BothWallsNeedPointsLabelledOnEach) {
  Frame frame;
  frame.points.push_back({1, Eigen::Vector3d::Zero(), WallLayer::kAnywhere});
  frame.points.push_back({2, Eigen::Vector3d::Zero(), WallLayer::kEndocardium});
  EXPECT_FALSE(HasBothWalls(frame));
  frame.points.push_back({3, Eigen::Vector3d::Zero(), WallLayer::kEpicardium});
  EXPECT_TRUE(HasBothWalls(frame));
  EXPECT_TRUE(HasBothWalls(std::vector<double>{0.0, 1.0, -1.0}));
  EXPECT_FALSE(HasBothWalls(std::vector<double>{0.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace pfdm
