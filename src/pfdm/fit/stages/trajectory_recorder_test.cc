#include "pfdm/fit/stages/trajectory_recorder.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

std::vector<int> Iterations(const std::vector<TrajectoryPoint>& trajectory) {
  std::vector<int> iterations;
  for (const TrajectoryPoint& point : trajectory) {
    iterations.push_back(point.iteration);
  }
  return iterations;
}

// One per decade keeps iterations 0, 9, 99 (the 1st, 10th and 100th) and
// the last, with the model as it was at each.
TEST(TrajectoryRecorderTest, KeepsLogSpacedStepsAndTheLast) {
  Model model = TestSpheroid(5);
  std::vector<TrajectoryPoint> trajectory;
  TrajectoryRecorder recorder(1, &model, &trajectory);
  for (int iteration = 0; iteration <= 150; ++iteration) {
    model.state.center[0] = iteration;
    recorder.Step(iteration, 0.5 * iteration);
  }
  recorder.Finish();
  EXPECT_EQ(Iterations(trajectory), (std::vector<int>{0, 9, 99, 150}));
  EXPECT_EQ(trajectory[1].state.center[0], 9.0);
  EXPECT_EQ(trajectory[1].pseudo_time, 4.5);
  EXPECT_EQ(trajectory[3].state.center[0], 150.0);
}

TEST(TrajectoryRecorderTest, KeepsTheLastStepOnce) {
  Model model = TestSpheroid(5);
  std::vector<TrajectoryPoint> trajectory;
  TrajectoryRecorder recorder(1, &model, &trajectory);
  for (int iteration = 0; iteration <= 9; ++iteration) {
    recorder.Step(iteration, 0.0);
  }
  recorder.Finish();
  EXPECT_EQ(Iterations(trajectory), (std::vector<int>{0, 9}));
}

// With none per decade the rounds record no step (GlobalRounds), and the
// end adds none.
TEST(TrajectoryRecorderTest, ZeroPerDecadeKeepsNothing) {
  Model model = TestSpheroid(5);
  std::vector<TrajectoryPoint> trajectory;
  TrajectoryRecorder recorder(0, &model, &trajectory);
  recorder.Finish();
  EXPECT_TRUE(trajectory.empty());
}

}  // namespace
}  // namespace pfdm
