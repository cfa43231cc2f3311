#include "pfdm/fit/stages/sequence_fit.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(SequenceFitTest, AddsEverySolveToTheFramesAccount) {
  SolverReport report;
  report.iterations = 4;
  report.residual_evaluations = 6;
  report.jacobian_evaluations = 5;
  report.evaluation_seconds = 0.25;
  report.linear_solver_seconds = 0.5;
  report.minimizer_seconds = 1.0;
  FrameFit fit;
  AddSolverCounts(report, &fit);
  AddSolverCounts(report, &fit);
  EXPECT_EQ(fit.iterations, 8);
  EXPECT_EQ(fit.residual_evaluations, 12);
  EXPECT_EQ(fit.jacobian_evaluations, 10);
  EXPECT_EQ(fit.evaluation_seconds, 0.5);
  EXPECT_EQ(fit.linear_solver_seconds, 1.0);
  EXPECT_EQ(fit.minimizer_seconds, 2.0);
}

TEST(SequenceFitTest, SaysHowFarUnsettledPointsMoved) {
  FrameFit fit;
  EXPECT_EQ(UnsettledNote(fit), "");
  fit.unsettled_mm = 0.937;
  EXPECT_EQ(UnsettledNote(fit),
            "; closest points unsettled (0.94 mm in the last search)");
}

// Frame 0 places the tracked frames' material points, so they carry its
// length draws; an untracked later frame's draws are not a stretch.
TEST(SequenceFitTest, TakesFrameZerosLengthDrawsOnTrackedFrames) {
  SequenceFit fit;
  fit.frames.resize(3);
  fit.frames[2].tracked = false;  // Contours.
  fit.frames[0].covariance.length_noise = {0.01, -0.01, 0.03};
  fit.frames[2].covariance.length_noise = {0.002, 0.004};
  // Mean 0.01, squares 0, 4e-4, 4e-4 over n - 1 = 2.
  EXPECT_NEAR(LengthVariance(fit, 0), 4e-4, 1e-15);
  EXPECT_NEAR(LengthVariance(fit, 1), 4e-4, 1e-15);
  EXPECT_EQ(LengthVariance(fit, 2), 0.0);
  fit.frames[0].covariance.length_noise = {0.002};
  EXPECT_EQ(LengthVariance(fit, 0), 0.0);
}

}  // namespace
}  // namespace pfdm
