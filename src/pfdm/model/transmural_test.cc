#include "pfdm/model/transmural.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/model/model.h"
#include "pfdm/model/model_point.h"
#include "pfdm/model/shape_jacobian.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

FunctionValues Sphere(double radius_mm, double wall_mm) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 2.0 * radius_mm;  // a1 = a2 = a3 = 0.5.
  f[kH] = wall_mm;
  return f;
}

// On a sphere the wall direction is radial: the endocardium and epicardium
// are the spheres h / 2 inside and outside, at every (u, v), poles included.
TEST(TransmuralTest, SphereWallsAreConcentricSpheres) {
  const FunctionValues f = Sphere(30.0, 10.0);
  for (double u : {-kHalfPi, -1.0, 0.0, 0.5}) {
    for (double v : {-3.0, 0.0, 1.0}) {
      const Angles<double> angles = MakeAngles(u, v);
      EXPECT_NEAR(ReferenceShape(f.data(), angles, true, -1.0).norm(), 25.0,
                  1e-12);
      EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 1.0).norm(), 35.0,
                  1e-12);
      const Eigen::Vector3d mid = ReferenceShape(f.data(), angles, true);
      EXPECT_TRUE(WallDirection(f.data(), angles).isApprox(mid / 30.0, 1e-12));
    }
  }
}

// The wall direction is the ellipsoid's normal: orthogonal to both tangents
// of the mid-wall when a1..a3 do not vary along u and nothing bends.
TEST(TransmuralTest, WallDirectionIsTheEllipsoidNormal) {
  FunctionValues f = Sphere(30.0, 8.0);
  f[kA1] = 0.4;
  f[kA2] = 0.3;
  f[kA3] = 0.9;
  const double step = 1e-6;
  for (double u : {-1.2, -0.3, 0.4}) {
    for (double v : {-2.0, 0.3, 2.5}) {
      auto at = [&](double uu, double vv) {
        return ReferenceShape(f.data(), MakeAngles(uu, vv), true);
      };
      const Eigen::Vector3d du = (at(u + step, v) - at(u - step, v)) / step;
      const Eigen::Vector3d dv = (at(u, v + step) - at(u, v - step)) / step;
      const Eigen::Vector3d n = WallDirection(f.data(), MakeAngles(u, v));
      EXPECT_NEAR(n.dot(du.normalized()), 0.0, 1e-8);
      EXPECT_NEAR(n.dot(dv.normalized()), 0.0, 1e-8);
      EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    }
  }
}

// shift moves both walls outward of the layer w = 0 and keeps them h apart.
TEST(TransmuralTest, ShiftMovesTheWallsOffTheMiddleLayer) {
  FunctionValues f = Sphere(30.0, 10.0);
  f[kWallShift] = 1.5;
  const Angles<double> angles = MakeAngles(-0.7, 2.0);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, -1.0).norm(), 26.5, 1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 0.0).norm(), 30.0, 1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 0.5).norm(), 32.875,
              1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 1.0).norm(), 36.5, 1e-12);
}

// squeeze moves the layers inside the wall, k(w) = w h / 2 + (w^3 - w) q,
// and leaves both walls and the middle layer where h and shift put them.
TEST(TransmuralTest, SqueezeMovesTheLayersInsideTheWallOnly) {
  FunctionValues f = Sphere(30.0, 10.0);
  f[kWallSqueeze] = 2.0;
  const Angles<double> angles = MakeAngles(0.3, -1.0);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, -1.0).norm(), 25.0, 1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 0.0).norm(), 30.0, 1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 1.0).norm(), 35.0, 1e-12);
  // w = 0.5: 2.5 + (0.125 - 0.5) 2 = 1.75 mm out, nearer the middle.
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, 0.5).norm(), 31.75, 1e-12);
  EXPECT_NEAR(ReferenceShape(f.data(), angles, true, -0.5).norm(), 28.25,
              1e-12);
  // The spacing at the middle layer is h / 2 - q per unit of w.
  const double step = 1e-6;
  const double spacing =
      (ReferenceShape(f.data(), angles, true, step).norm() -
       ReferenceShape(f.data(), angles, true, -step).norm()) /
      (2.0 * step);
  EXPECT_NEAR(spacing, 3.0, 1e-6);
}

// tau is the mid-wall's twist; the endocardium turns dtau / 2 less and the
// epicardium dtau / 2 more.
TEST(TransmuralTest, TwistDifferenceSplitsAcrossTheWall) {
  FunctionValues f = Sphere(30.0, 10.0);
  f[kTau] = 0.2;
  f[kDtau] = -0.1;
  const Angles<double> angles = MakeAngles(0.0, 0.0);
  for (double w : {-1.0, 0.0, 1.0}) {
    const Eigen::Vector3d p = ReferenceShape(f.data(), angles, true, w);
    EXPECT_NEAR(std::atan2(p.y(), p.x()), 0.2 - 0.05 * w, 1e-12) << w;
  }
}

TEST(TransmuralTest, ShapeJacobianMatchesReferenceShapeOffTheMidwall) {
  FunctionValues f = Sphere(35.0, 9.0);
  f[kA1] = 0.3;
  f[kEps1] = 0.7;
  f[kB0] = 2.0;
  f[kB1] = 0.2;
  f[kTau] = 0.4;
  f[kDtau] = 0.1;
  f[kWallShift] = -0.8;
  f[kWallSqueeze] = 0.6;
  for (double w : {-1.0, -0.3, 0.0, 0.55, 1.0}) {
    for (double u : {-kHalfPi, -0.5, 0.4}) {
      const Angles<double> angles = MakeAngles(u, 1.2);
      ShapeJacobian jacobian;
      EXPECT_TRUE(
          ShapeAndJacobian(f.data(), angles, false, &jacobian, w)
              .isApprox(ReferenceShape(f.data(), angles, false, w), 1e-14));
      for (int c = 0; c < kNumFunctions; ++c) {
        FunctionValues plus = f, minus = f;
        const double step = 1e-6 * std::max(1.0, std::abs(f[c]));
        plus[c] += step;
        minus[c] -= step;
        const Eigen::Vector3d numeric =
            (ReferenceShape(plus.data(), angles, false, w) -
             ReferenceShape(minus.data(), angles, false, w)) /
            (2.0 * step);
        EXPECT_LT((jacobian.col(c) - numeric).norm(), 1e-6) << c << " " << w;
      }
    }
  }
}

TEST(TransmuralTest, ModelPointsOfTheWalls) {
  ModelConfig config = ModelConfig::Paper(5);
  config.MakeSolid();
  EXPECT_TRUE(config.Solid());
  EXPECT_FALSE(ModelConfig::Paper(5).Solid());
  const Model model = Model::Uniform(config, Sphere(30.0, 12.0));
  EXPECT_NEAR(model.ModelPoint(-0.2, 1.0, -1.0).norm(), 24.0, 1e-12);
  EXPECT_NEAR(model.WorldPoint(-0.2, 1.0, 1.0).norm(), 36.0, 1e-12);
  EXPECT_EQ(model.ModelPoint(-0.2, 1.0), model.ModelPoint(-0.2, 1.0, 0.0));
}

}  // namespace
}  // namespace pfdm
