#include "pfdm/report/material_myocardium.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 0.5 * kPi;

// The shell between latitudes u0 and u1: (2 pi / 3)(R^3 - r^3)(sin u1 -
// sin u0), ml.
double ShellZoneMl(double u0, double u1) {
  return 2.0 * kPi / 3.0 * (35.0 * 35.0 * 35.0 - 25.0 * 25.0 * 25.0) *
         (std::sin(u1) - std::sin(u0)) / 1000.0;
}

TEST(MaterialMyocardiumTest, SphericalShellZonesAndTheWholeCup) {
  const Model shell = TestShell(5);
  // Triangulated: within 0.5 % of the exact zone (chords cut the curve).
  const double zone = ShellZoneMl(-0.5, 0.4);
  EXPECT_NEAR(MaterialMyocardiumMl(shell, -0.5, 0.4), zone, 0.005 * zone);
  const double cup = ShellZoneMl(-kHalfPi, 0.3);
  EXPECT_NEAR(MaterialMyocardiumMl(shell, -kHalfPi, 0.3), cup, 0.005 * cup);
}

// The volume is the material's: a rigid motion does not change it, a
// squeeze (layers moved inside the wall, walls held) does not either, and
// a thicker wall holds more.
TEST(MaterialMyocardiumTest, RigidMotionAndSqueezeKeepItThickeningAddsToIt) {
  Model shell = TestShell(5);
  const double before = MaterialMyocardiumMl(shell, -0.8, 0.5);
  shell.state.center = {10.0, -4.0, 7.0};
  const double norm = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
  shell.state.quaternion = {0.9 / norm, 0.1 / norm, -0.3 / norm, 0.2 / norm};
  EXPECT_NEAR(MaterialMyocardiumMl(shell, -0.8, 0.5), before, 1e-9 * before);
  for (FunctionValues& knot : shell.state.knots) knot[kWallSqueeze] = 1.5;
  EXPECT_NEAR(MaterialMyocardiumMl(shell, -0.8, 0.5), before, 1e-3 * before);
  for (FunctionValues& knot : shell.state.knots) knot[kH] = 12.0;
  // Walls 24 to 36 mm: (36^3 - 24^3) / (35^3 - 25^3) = 1.20484.
  EXPECT_NEAR(MaterialMyocardiumMl(shell, -0.8, 0.5) / before, 1.20484, 1e-3);
}

}  // namespace
}  // namespace pfdm
