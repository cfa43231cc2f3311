#include "pfdm/fit/stages/round_acceleration.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A fixed-point map q -> G(q) = q* + A (q - q*) with the two behaviours of
// biv-me's correspondence rounds: a mode that overshoots (eigenvalue -1.3:
// plain iteration swings ever wider, as frames 6 and 13 did) and one that
// creeps (0.9: frame 1's slow drift), coupled by a rotation.
struct LinearMap {
  Eigen::Matrix2d a;
  Eigen::Vector2d fixed{3.0, -2.0};
  LinearMap() {
    Eigen::Matrix2d rotation;
    const double c = std::cos(0.4), s = std::sin(0.4);
    rotation << c, -s, s, c;
    a = rotation * Eigen::Vector2d(-1.3, 0.9).asDiagonal() *
        rotation.transpose();
  }
  Eigen::Vector2d operator()(const Eigen::Vector2d& q) const {
    return fixed + a * (q - fixed);
  }
};

TEST(RoundAccelerationTest, SettlesALinearMapThatPlainIterationCannot) {
  const LinearMap map;
  Eigen::Vector2d plain(0.0, 0.0), mixed(0.0, 0.0);
  RoundAcceleration acceleration(2);
  for (int round = 0; round < 10; ++round) {
    plain = map(plain);
    const Eigen::Vector2d solved = map(mixed);
    mixed = acceleration.Next(solved - mixed, solved);
  }
  // Plain: the overshooting mode has grown 1.3^10 = 14-fold.
  EXPECT_GT((plain - map.fixed).norm(), 10.0);
  // Two recorded differences span the plane: the mix is exact from the
  // third round on (to round-off).
  EXPECT_LT((mixed - map.fixed).norm(), 1e-9);
  EXPECT_EQ(acceleration.restarts(), 0);
}

TEST(RoundAccelerationTest, FirstRoundAndRestartGiveTheSolution) {
  RoundAcceleration acceleration(2);
  const Eigen::Vector2d first(1.0, 2.0);
  EXPECT_EQ(acceleration.Next(Eigen::Vector2d(1.0, 0.0), first), first);
  // A change of more than twice the smallest so far: the history restarts
  // and the solution is taken as it is.
  const Eigen::Vector2d second(5.0, 6.0);
  EXPECT_EQ(acceleration.Next(Eigen::Vector2d(3.0, 0.0), second), second);
  EXPECT_EQ(acceleration.restarts(), 1);
}

// A one-dimensional map with slope -1 swings between two values for ever;
// one secant step (memory 1) lands on its fixed point.
TEST(RoundAccelerationTest, OneSecantStepEndsATwoCycle) {
  auto map = [](double q) { return 4.0 - q; };  // Fixed point 2.
  RoundAcceleration acceleration(1);
  double q = 0.0;
  for (int round = 0; round < 2; ++round) {
    const double solved = map(q);
    q = acceleration.Next(Eigen::VectorXd::Constant(1, solved - q),
                          Eigen::VectorXd::Constant(1, solved))[0];
  }
  EXPECT_NEAR(q, 2.0, 1e-12);
}

TEST(RoundAccelerationTest, StateVectorRoundTripsAndNormalizes) {
  Model model = TestSpheroid(6);
  model.state.center = {1.0, 2.0, 3.0};
  model.state.quaternion = {2.0, 0.0, 0.0, 0.0};
  model.state.knots[2][kA1] = 0.7;
  const Eigen::VectorXd vector = StateVector(model.state);
  EXPECT_EQ(vector.size(), 7 + 7 * kNumFunctions);  // Globals, 6 knots.
  ModelState back = model.state;
  back.knots[2][kA1] = 0.0;
  SetStateVector(vector, &back);
  EXPECT_EQ(back.center, model.state.center);
  EXPECT_DOUBLE_EQ(back.quaternion[0], 1.0);  // Normalized.
  EXPECT_DOUBLE_EQ(back.knots[2][kA1], 0.7);
  EXPECT_EQ(back.globals, model.state.globals);
}

}  // namespace
}  // namespace pfdm
