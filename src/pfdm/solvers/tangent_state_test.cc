// The integrators' tangent state on the toy problems: the stiffest rate,
// moves into the bounds, and the force a bound holds.
#include "pfdm/solvers/tangent_state.h"

#include <optional>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/testing/toy_problems.h"

namespace pfdm {
namespace {

// Power iteration finds lambda_max of D^-1/2 J^T J D^-1/2 to its 1e-4.
TEST(TangentStateTest, LargestEigenvalueIsTheStiffestJacobiRate) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.options.damping = DampingKind::kJacobi;
  const State state = FreeBlocks(toy.problem);
  ASSERT_EQ(state.tangent_size, 2);
  Evaluation e;
  ASSERT_TRUE(Evaluate(&toy.problem, state, 1, true, &e));
  std::string error;
  const std::optional<std::vector<double>> d =
      Damping(toy.problem, state, e.jacobian, toy.options, &error);
  ASSERT_TRUE(d.has_value()) << error;
  EXPECT_NEAR(LargestEigenvalue(e.jacobian, *d), 2.0 / LinearStabilityBound(),
              1e-3);
}

// Place moves from a snapshot, not from where the blocks are, and clips;
// HoldAtBounds then drops the velocity that pushes through the bound.
TEST(TangentStateTest, PlaceClipsAndHoldAtBoundsDropsTheOutwardPush) {
  LinearToyProblem toy(SolverKind::kIntegrator);
  toy.problem.SetParameterUpperBound(toy.x, 0, 0.5);
  toy.x[0] = 0.0;
  const State state = FreeBlocks(toy.problem);
  const std::vector<double> base = Snapshot(state);
  toy.x[0] = 7.0;  // Overwritten by Place.
  ASSERT_TRUE(Place(&toy.problem, state, base, {2.0, 1.0}));
  EXPECT_EQ(toy.x[0], 0.5);
  EXPECT_EQ(toy.x[1], -2.0);
  std::vector<double> velocity = {1.0, 3.0};
  HoldAtBounds(toy.problem, state, &velocity);
  EXPECT_EQ(velocity, (std::vector<double>{0.0, 3.0}));
  velocity = {-1.0, 3.0};  // Back into the box: free.
  HoldAtBounds(toy.problem, state, &velocity);
  EXPECT_EQ(velocity, (std::vector<double>{-1.0, 3.0}));
}

}  // namespace
}  // namespace pfdm
