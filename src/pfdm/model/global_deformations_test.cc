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
  const Eigen::Vector3d twisted = Twist(f[kTau], e);
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

TEST(BendTest, TiltAndCupFollowEquationSevenLessTheRingMean) {
  FunctionValues f = Values();
  f[kB0] = 2.0;
  f[kB1] = 1.0;  // Tilt: b0 sin(pi/2 e1/a0), whose ring mean is 0.
  f[kB2] = 3.0;
  f[kB3] = 0.0;  // Cup: b2 (cos(pi/2 e2/a0) - J0(pi/2 r2)).
  const Eigen::Vector3d e(10.0, -20.0, 5.0);
  const Eigen::Vector2d ring(0.3, 0.45);
  const Eigen::Vector3d bent = Bend(f.data(), e, ring);
  const double expected_dz = 2.0 * std::sin(M_PI / 2 * 10.0 / 50.0) +
                             3.0 * (std::cos(M_PI / 2 * -20.0 / 50.0) -
                                    std::cyl_bessel_j(0.0, M_PI / 2 * 0.45));
  EXPECT_NEAR(bent.z() - e.z(), expected_dz, 1e-12);
  EXPECT_EQ(bent.x(), e.x());
  EXPECT_EQ(bent.y(), e.y());
}

// Why a whole shape function may shift by 2 (Model::CanonicalizeBending).
TEST(BendTest, ShiftingTheShapeByTwoFlipsTheAmplitude) {
  for (double x : {-0.9, -0.2, 0.0, 0.35, 1.0}) {
    for (double b : {0.0, 0.4, 1.0, 1.7}) {
      for (double r : {0.0, 0.3, 1.0}) {
        EXPECT_NEAR(BendProfile(x, b + 2.0, r), -BendProfile(x, b, r), 1e-12);
      }
    }
  }
  FunctionValues f = Values(), flipped = Values();
  f[kB0] = 3.0, f[kB1] = 0.6;
  flipped[kB0] = -3.0, flipped[kB1] = 2.6;
  const Eigen::Vector3d e(12.0, -7.0, 4.0);
  const Eigen::Vector2d ring(0.4, 0.3);
  EXPECT_TRUE(
      Bend(f.data(), e, ring).isApprox(Bend(flipped.data(), e, ring), 1e-12));
  EXPECT_GT(std::abs(Bend(f.data(), e, ring).z() - e.z()), 0.5);
}

// The bend moves points along the axis by where they sit across the ring,
// but the ring's mean height (over v, the ring of an ellipse with the given
// half extents) stays: any tilt, cup or mix, any ring size.
TEST(BendTest, NeverMovesARingsMeanHeight) {
  const int n = 512;  // Trapezoid rule: exact to rounding for periodic g.
  for (double b1 : {0.0, 0.3, 1.0, 1.6}) {
    for (Eigen::Vector2d ring :
         {Eigen::Vector2d(0.3, 0.25), Eigen::Vector2d(0.9, 1.0),
          Eigen::Vector2d(0.0, 0.0)}) {
      FunctionValues f = Values();
      f[kB0] = 9.0, f[kB1] = b1, f[kB2] = -4.0, f[kB3] = 0.5 * b1;
      double mean = 0.0;
      for (int j = 0; j < n; ++j) {
        const double v = 2.0 * M_PI * j / n;
        const Eigen::Vector3d e(50.0 * ring[0] * std::cos(v),
                                50.0 * ring[1] * std::sin(v), -12.0);
        mean += Bend(f.data(), e, ring).z() / n;
      }
      EXPECT_NEAR(mean, -12.0, 1e-12) << b1 << " " << ring.transpose();
    }
  }
  const FunctionValues straight = Values();
  const Eigen::Vector3d e(3.0, 4.0, 5.0);
  EXPECT_TRUE(Bend(straight.data(), e, Eigen::Vector2d(0.2, 0.3)).isApprox(e));
}

}  // namespace
}  // namespace pfdm
