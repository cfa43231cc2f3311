#include "pfdm/fit/round_relaxation.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

Eigen::Vector3d Center(const Model& model) {
  return Eigen::Vector3d(model.state.center.data());
}

// Another solve's answer: shifted along x by `shift` mm, a1 and tau moved
// by `change`, and turned by `angle` about y.
Model Moved(const Model& model, double shift, double change, double angle) {
  Model moved = model;
  moved.state.center[0] += shift;
  for (FunctionValues& knot : moved.state.knots) {
    knot[kA1] += change;
    knot[kTau] += change;
  }
  moved.state.quaternion = {std::cos(angle / 2), 0.0, std::sin(angle / 2), 0.0};
  return moved;
}

TEST(RoundRelaxationTest, BlendGoesTheShareOfTheWayAndKeepsAUnitQuaternion) {
  const Model from = TestSpheroid(5);
  const Model to = Moved(from, 2.0, 0.1, 0.2);
  const ModelState half = BlendStates(from.state, to.state, 0.5);
  EXPECT_DOUBLE_EQ(half.center[0], from.state.center[0] + 1.0);
  for (size_t k = 0; k < half.knots.size(); ++k) {
    EXPECT_DOUBLE_EQ(half.knots[k][kA1], from.state.knots[k][kA1] + 0.05);
    EXPECT_DOUBLE_EQ(half.knots[k][kTau], from.state.knots[k][kTau] + 0.05);
  }
  // Half the turn about y, normalized.
  EXPECT_NEAR(half.quaternion[0], std::cos(0.05), 1e-15);
  EXPECT_NEAR(half.quaternion[2], std::sin(0.05), 1e-15);
  // -q is q's rotation: the blend must not pass through the identity's
  // opposite.
  ModelState flipped = to.state;
  for (double& q : flipped.quaternion) q = -q;
  const ModelState half_flipped = BlendStates(from.state, flipped, 0.5);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(half_flipped.quaternion[i], half.quaternion[i], 1e-15) << i;
  }
  const ModelState same = BlendStates(from.state, to.state, 1.0);
  EXPECT_EQ(same.center, to.state.center);
  EXPECT_EQ(same.knots, to.state.knots);
}

// A 2-cycle (A -> B -> A) is cut at its middle; rounds that keep going one
// way, or stop, are left alone.
TEST(RoundRelaxationTest, HalvesAMoveBackAndLeavesOthersAlone) {
  const Model a = TestSpheroid(5);
  const Model b = Moved(a, 1.0, 0.02, 0.02);
  RoundRelaxation cycle(a.config);
  Model after = b;
  EXPECT_FALSE(cycle.AfterSolve(a, &after));  // Nothing to compare yet.
  EXPECT_EQ(after.state.center, b.state.center);
  after = a;
  EXPECT_TRUE(cycle.AfterSolve(b, &after));
  EXPECT_NEAR((Center(after) - 0.5 * (Center(a) + Center(b))).norm(), 0.0,
              1e-12);
  for (size_t k = 0; k < a.state.knots.size(); ++k) {
    EXPECT_NEAR(after.state.knots[k][kA1],
                0.5 * (a.state.knots[k][kA1] + b.state.knots[k][kA1]), 1e-15);
  }
  // From the middle on toward a, as the halved move went: no reversal.
  const Model middle = after;
  after = Moved(middle, -0.1, -0.002, 0.0);
  after.state.quaternion = middle.state.quaternion;
  EXPECT_FALSE(cycle.AfterSolve(middle, &after));

  RoundRelaxation onward(a.config);
  after = b;
  EXPECT_FALSE(onward.AfterSolve(a, &after));
  const Model c = Moved(b, 0.5, 0.01, 0.03);
  after = c;
  EXPECT_FALSE(onward.AfterSolve(b, &after));
  EXPECT_EQ(after.state.center, c.state.center);
  after = c;
  EXPECT_FALSE(onward.AfterSolve(c, &after));  // A solve that stays put.
}

}  // namespace
}  // namespace pfdm
