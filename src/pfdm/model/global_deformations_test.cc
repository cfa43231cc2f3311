#include "pfdm/model/global_deformations.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

FunctionValues Values() {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 50.0;
  return f;
}

TEST(TwistTest, RotatesRightHandedAboutTheLongAxis) {
  FunctionValues f = Values();
  f[kTau] = 0.3;
  const Eigen::Vector3d e(10.0, 0.0, 7.0);
  const Eigen::Vector3d twisted = Twist(f.data(), e);
  EXPECT_NEAR(std::atan2(twisted.y(), twisted.x()), 0.3, 1e-12);
  EXPECT_NEAR(twisted.head<2>().norm(), 10.0, 1e-12);
  EXPECT_EQ(twisted.z(), 7.0);
}

TEST(OffsetTest, TranslatesByTheOffsets) {
  FunctionValues f = Values();
  f[kE1o] = 1.5;
  f[kE2o] = -2.0;
  f[kE3o] = 0.25;
  const Eigen::Vector3d moved = Offset(f.data(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(moved.isApprox(Eigen::Vector3d(2.5, 0.0, 3.25)));
}

TEST(BendTest, TiltAndCupFollowEquationSeven) {
  FunctionValues f = Values();
  f[kB0] = 2.0;
  f[kB1] = 1.0;  // Tilt: b0 sin(pi/2 e1/a0).
  f[kB2] = 3.0;
  f[kB3] = 0.0;  // Cup: b2 (cos(pi/2 e2/a0) - 1).
  const Eigen::Vector3d e(10.0, -20.0, 5.0);
  const Eigen::Vector3d bent = Bend(f.data(), e);
  const double expected_dz = 2.0 * std::sin(M_PI / 2 * 10.0 / 50.0) +
                             3.0 * (std::cos(M_PI / 2 * -20.0 / 50.0) - 1.0);
  EXPECT_NEAR(bent.z() - e.z(), expected_dz, 1e-12);
  EXPECT_EQ(bent.x(), e.x());
  EXPECT_EQ(bent.y(), e.y());
}

// Why the fit holds b1 and b3 to a window of width 2 (fitter.cc).
TEST(BendTest, ShiftingTheShapeByTwoFlipsTheAmplitude) {
  for (double x : {-0.9, -0.2, 0.0, 0.35, 1.0}) {
    for (double b : {0.0, 0.4, 1.0, 1.7}) {
      EXPECT_NEAR(BendProfile(x, b + 2.0), -BendProfile(x, b), 1e-12);
    }
  }
  FunctionValues f = Values(), flipped = Values();
  f[kB0] = 3.0, f[kB1] = 0.6;
  flipped[kB0] = -3.0, flipped[kB1] = 2.6;
  const Eigen::Vector3d e(12.0, -7.0, 4.0);
  EXPECT_TRUE(Bend(f.data(), e).isApprox(Bend(flipped.data(), e), 1e-12));
  EXPECT_GT(std::abs(Bend(f.data(), e).z() - e.z()), 0.5);
}

TEST(BendTest, LeavesTheRingCentreAndZeroBendInPlace) {
  FunctionValues f = Values();
  f[kB0] = 4.0;
  f[kB1] = 0.3;
  f[kB2] = -1.0;
  f[kB3] = -0.6;
  const Eigen::Vector3d centre(0.0, 0.0, -12.0);
  EXPECT_TRUE(Bend(f.data(), centre).isApprox(centre));
  const FunctionValues straight = Values();
  const Eigen::Vector3d e(3.0, 4.0, 5.0);
  EXPECT_TRUE(Bend(straight.data(), e).isApprox(e));
}

}  // namespace
}  // namespace pfdm
