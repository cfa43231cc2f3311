#include "pfdm/model/wall_volume.h"

#include <cmath>

#include "ceres/jet.h"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 0.5 * kPi;

// The shell between latitudes u0 and u1: (2 pi / 3)(R^3 - r^3)(sin u1 -
// sin u0), mm^3.
double ShellZone(double outer, double inner, double u0, double u1) {
  return 2.0 * kPi / 3.0 * (outer * outer * outer - inner * inner * inner) *
         (std::sin(u1) - std::sin(u0));
}

TEST(WallVolumeTest, SphericalShellZoneFromTheApex) {
  const Model shell = TestShell(5);
  const FunctionValues f = shell.FunctionsAt(0.0);
  const double exact = ShellZone(35.0, 25.0, -kHalfPi, 0.4);
  // Fine: chords and polygon sides cut the curved walls by under 0.1 %.
  EXPECT_NEAR(WallVolume(f.data(), f.data(), -kHalfPi, 0.4, true, 64, 256),
              exact, 1e-3 * exact);
  // The residual's grid over a knot span: a 16-gon's area is
  // sin(pi / 8) / (pi / 8) = 0.97449 of its circle's, and the chords along
  // u cut 0.25 % more.
  const double span = ShellZone(35.0, 25.0, 0.0, 0.1);
  EXPECT_NEAR(WallVolume(f.data(), f.data(), 0.0, 0.1, true, 1, 16),
              0.97449 * span, 5e-3 * span);
}

TEST(WallVolumeTest, SpansAddUpToTheModelsWall) {
  const Model shell = TestShell(9);
  const ModelConfig& config = shell.config;
  const double exact = ShellZone(35.0, 25.0, config.u_min, config.u_max);
  EXPECT_NEAR(ModelWallVolume(shell, config.u_min, config.u_max, 8, 256), exact,
              1e-3 * exact);
  Model no_wall = shell;
  no_wall.config.modes[kH] = FunctionMode::kFixed;
  EXPECT_EQ(ModelWallVolume(no_wall, config.u_min, config.u_max, 8, 256), 0.0);
  // Rings between the knots: the zone between them.
  const double zone = ShellZone(35.0, 25.0, -0.61, 0.33);
  EXPECT_NEAR(ModelWallVolume(shell, -0.61, 0.33, 8, 256), zone, 1e-3 * zone);
}

// Thickening: walls 24 to 36 mm hold (36^3 - 24^3) / (35^3 - 25^3) =
// 1.20484 times as much; a shift of 1 mm outward, walls 26 to 36 mm,
// (36^3 - 26^3) / (35^3 - 25^3) = 1.06716.  The 16-gon's ratios agree
// with the exact ones within 1e-3.
TEST(WallVolumeTest, ThickeningAndShiftChangeItAsTheShellsDo) {
  Model shell = TestShell(5);
  const double before = ModelWallVolume(shell, -0.6, 0.3, 1, 16);
  for (FunctionValues& knot : shell.state.knots) knot[kH] = 12.0;
  EXPECT_NEAR(ModelWallVolume(shell, -0.6, 0.3, 1, 16) / before, 1.20484, 1e-3);
  for (FunctionValues& knot : shell.state.knots) {
    knot[kH] = 10.0;
    knot[kWallShift] = 1.0;
  }
  EXPECT_NEAR(ModelWallVolume(shell, -0.6, 0.3, 1, 16) / before, 1.06716, 1e-3);
  // The squeeze moves the layers between the walls only.
  for (FunctionValues& knot : shell.state.knots) knot[kWallSqueeze] = 1.5;
  EXPECT_NEAR(ModelWallVolume(shell, -0.6, 0.3, 1, 16) / before, 1.06716, 1e-3);
}

// Jets carry the derivative: d V / d h of the shell zone against a central
// difference, at the apex pole included.
TEST(WallVolumeTest, JetDerivativeMatchesCentralDifference) {
  using Jet = ceres::Jet<double, 1>;
  const Model shell = TestShell(5);
  const FunctionValues f = shell.FunctionsAt(0.0);
  Jet low[kNumFunctions], high[kNumFunctions];
  for (int n = 0; n < kNumFunctions; ++n) low[n] = high[n] = Jet(f[n]);
  low[kH].v[0] = 1.0;  // Only the apical ring's h varies.
  const Jet volume = WallVolume(low, high, -kHalfPi, 0.2, true, 4, 32);
  const double step = 1e-5;
  FunctionValues up = f, down = f;
  up[kH] += step;
  down[kH] -= step;
  const double difference =
      (WallVolume(up.data(), f.data(), -kHalfPi, 0.2, true, 4, 32) -
       WallVolume(down.data(), f.data(), -kHalfPi, 0.2, true, 4, 32)) /
      (2.0 * step);
  EXPECT_NEAR(volume.v[0], difference, 1e-6 * std::abs(difference));
  EXPECT_GT(difference, 0.0);
}

}  // namespace
}  // namespace pfdm
