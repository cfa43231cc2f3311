#include "pfdm/fit/correspondence/tangential_stretch.h"

#include <cmath>
#include <cstdio>
#include <random>

#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// The shell with its radius along x (a1) contracted by `scale` and its wall
// `h_scale` times as thick.
Model ContractedShell(double scale, double h_scale) {
  Model model = TestShell(5);
  for (FunctionValues& knot : model.state.knots) {
    knot[kA1] *= scale;
    knot[kH] *= h_scale;
  }
  return model;
}

TEST(TangentialStretchTest, TwoWhereNothingMovedAndAtThePole) {
  const Model shell = TestShell(5);
  const std::vector<MaterialPoint> at = {
      {0.0, 0.3, 0.0}, {-0.7, 2.0, 0.8}, {shell.config.u_min, 1.0, -0.5}};
  for (double s : TangentialStretchSquared(shell, shell, at)) {
    EXPECT_NEAR(s, 2.0, 1e-12);
  }
  // The pole's metric is singular whatever the later frame does.
  const std::vector<double> pole =
      TangentialStretchSquared(shell, ContractedShell(0.8, 1.0), {at[2]});
  EXPECT_EQ(pole[0], 2.0);
}

// On the equator the x radius' contraction stretches dx/dv alone, and
// only where v points it along x.
TEST(TangentialStretchTest, ContractionAlongXOnTheEquator) {
  const Model shell = TestShell(5);
  const std::vector<double> s =
      TangentialStretchSquared(shell, ContractedShell(0.8, 1.0),
                               {{0.0, 0.0, 0.0}, {0.0, 0.5 * kPi, 0.0}});
  EXPECT_NEAR(s[0], 2.0, 1e-9);
  EXPECT_NEAR(s[1], 1.0 + 0.64, 1e-9);
}

// Measured a second way: frame 0's tangential noise drawn in the world,
// carried to (u, v) by frame 0's tangents and out again by the later
// frame's model; its mean square over sigma^2 is |F|^2.
TEST(TangentialStretchTest, IsWhatFrameZerosNoiseBecomes) {
  const Model first = TestShell(5);
  const Model later = ContractedShell(0.8, 1.3);
  const MaterialPoint at{-0.4, 2.2, 0.6};
  const double stretch = TangentialStretchSquared(first, later, {at})[0];
  const Eigen::Matrix<double, 3, 2> tangents = SurfaceTangents(first, {at})[0];
  const Eigen::Vector3d normal = SurfaceNormal(first, at.u, at.v, at.w);
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Eigen::Vector3d x = later.WorldPoint(at.u, at.v, at.w);
  double sum = 0.0;
  constexpr int kDraws = 20000;
  for (int i = 0; i < kDraws; ++i) {
    Eigen::Vector3d e(noise(random), noise(random), noise(random));
    e -= e.dot(normal) * normal;
    const Eigen::Vector2d duv = tangents.colPivHouseholderQr().solve(e);
    sum += (later.WorldPoint(at.u + duv[0], at.v + duv[1], at.w) - x)
               .squaredNorm();
  }
  const double measured = sum / kDraws / (0.01 * 0.01);
  std::printf("|F|^2 %.4f, measured %.4f\n", stretch, measured);
  EXPECT_LT(stretch, 1.9);
  EXPECT_NEAR(measured, stretch, 0.03 * stretch);
}

}  // namespace
}  // namespace pfdm
