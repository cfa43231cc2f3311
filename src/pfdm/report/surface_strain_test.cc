#include "pfdm/report/surface_strain.h"

#include <cmath>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

Model Sphere(double radius_fraction) {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = values[kA3] = radius_fraction;
  return Model::Uniform(ModelConfig::Paper(17), values);
}

constexpr double kTolerance = 1e-7;

// The closed-form tangents are the central differences of WorldPoint, on a
// model with every kind of motion: functions varying along u, bends, a
// local field and a pose.  Away from knots and element edges, where the
// difference would straddle two slopes.
TEST(SurfaceStrainTest, TangentsAreTheDerivativesOfTheWorldPoint) {
  Model model = Sphere(0.7);
  const int k = model.config.num_knots;
  for (int i = 0; i < k; ++i) {
    model.state.knots[i][kA1] = 0.6 + 0.01 * i;
    model.state.knots[i][kTau] = 0.02 * i - 0.1;
    model.state.knots[i][kE1o] = 2.0 * std::sin(i);
  }
  model.state.globals[kB0] = 0.05;
  model.state.center = {3.0, -4.0, 5.0};
  model.state.quaternion = {0.9, 0.1, -0.3, 0.2};
  const double norm = Eigen::Vector4d(0.9, 0.1, -0.3, 0.2).norm();
  for (double& q : model.state.quaternion) q /= norm;
  AddTestLocalField(1.0, &model);
  const double h = 1e-6;
  for (double u : {-1.23, -0.41, 0.07, 0.43}) {
    const RingFunctions ring(model, u);
    for (double v : {-2.93, 0.31, 1.77}) {
      Eigen::Vector3d xu, xv;
      SurfaceTangents(model, ring, v, &xu, &xv);
      const Eigen::Vector3d du =
          (model.WorldPoint(u + h, v) - model.WorldPoint(u - h, v)) / (2 * h);
      const Eigen::Vector3d dv =
          (model.WorldPoint(u, v + h) - model.WorldPoint(u, v - h)) / (2 * h);
      EXPECT_LT((xu - du).norm(), 1e-6 * du.norm()) << u << " " << v;
      EXPECT_LT((xv - dv).norm(), 1e-6 * dv.norm()) << u << " " << v;
    }
  }
}

// Each layer of a bent, twisted solid with a transmural local field: the
// closed-form tangents of surface w are the central differences of
// WorldPoint(u, v, w), the endocardium's and the epicardium's as the
// mid-wall's.
TEST(SurfaceStrainTest, EachLayersTangentsAreItsWorldPointsDerivatives) {
  Model model = TestShell(17);
  for (int i = 0; i < model.config.num_knots; ++i) {
    model.state.knots[i][kB0] = 3.0 - 0.4 * i;
    model.state.knots[i][kTau] = 0.05 * i;
    model.state.knots[i][kH] = 9.0 + 0.2 * i;
  }
  model.state.globals[kB0] = 1.0;
  AddTestLocalField(1.5, &model);
  LocalField& field = model.state.local;
  field.slope.resize(field.values.size());
  for (size_t i = 0; i < field.slope.size(); ++i) {
    field.slope[i] = 0.8 * std::cos(2.3 * i);
  }
  const double h = 1e-6;
  for (double w : {-1.0, -0.35, 0.0, 1.0}) {
    for (double u : {-1.23, -0.41, 0.07, 0.43}) {
      const RingFunctions ring(model, u);
      for (double v : {-2.93, 0.31, 1.77}) {
        Eigen::Vector3d xu, xv;
        SurfaceTangents(model, ring, v, w, &xu, &xv);
        const Eigen::Vector3d du =
            (model.WorldPoint(u + h, v, w) - model.WorldPoint(u - h, v, w)) /
            (2 * h);
        const Eigen::Vector3d dv =
            (model.WorldPoint(u, v + h, w) - model.WorldPoint(u, v - h, w)) /
            (2 * h);
        EXPECT_LT((xu - du).norm(), 1e-6 * du.norm()) << w << " " << u;
        EXPECT_LT((xv - dv).norm(), 1e-6 * dv.norm()) << w << " " << u;
      }
    }
  }
}

// A ring on a knot, where a1 bends from rising to falling: its slopes are
// the mean of the two spans', as central differences across the knot read
// X_u; off the knot, the span's own slopes to the bit.
TEST(SurfaceStrainTest, ARingOnAKnotTakesBothSpansSlopes) {
  Model model = Sphere(0.7);
  const KnotGrid& grid = model.config.Grid();
  const int knot = 6;
  for (int i = 0; i < model.config.num_knots; ++i) {
    model.state.knots[i][kA1] = 0.7 - 0.02 * std::abs(i - knot);
  }
  const double u = grid.KnotU(knot);
  const RingFunctions on(model, u);
  const double rising = 0.02 / (u - grid.KnotU(knot - 1));
  const double falling = -0.02 / (grid.KnotU(knot + 1) - u);
  EXPECT_NEAR(on.slopes[kA1], 0.5 * (rising + falling), 1e-12);
  const double h = 1e-7;
  for (double v : {-2.0, 0.1}) {
    Eigen::Vector3d xu, xv;
    SurfaceTangents(model, on, v, &xu, &xv);
    const Eigen::Vector3d du =
        (model.WorldPoint(u + h, v) - model.WorldPoint(u - h, v)) / (2 * h);
    EXPECT_LT((xu - du).norm(), 1e-6 * du.norm()) << v;
  }
  const double between = 0.5 * (grid.KnotU(knot) + grid.KnotU(knot + 1));
  const RingFunctions off(model, between);
  EXPECT_EQ(off.slopes, model.FunctionSlopesAt(between));
  EXPECT_LT(off.slopes[kA1], -0.01);
}

TEST(SurfaceStrainTest, ScalingASphereStrainsBothWaysAlike) {
  const Model reference = Sphere(0.8);
  const double s = 0.85;
  const Model scaled = Sphere(0.8 * s);
  for (double u : {-1.2, -0.4, 0.0, 0.45}) {
    for (double v : {-2.9, 0.3, 1.7}) {
      const SurfaceStrain e = StrainAt(reference, scaled, u, v);
      EXPECT_NEAR(e.ecc, (s * s - 1) / 2, kTolerance) << u << " " << v;
      EXPECT_NEAR(e.ell, (s * s - 1) / 2, kTolerance) << u << " " << v;
      EXPECT_NEAR(e.ecl, 0.0, kTolerance) << u << " " << v;
    }
  }
}

// tau(u) = c u turns a ring of the sphere by c u about its axis: the
// longitudinal line element e_l gains cos(u) c along e_c, so
// C_cc = 1, C_ll = 1 + (c cos u)^2, C_cl = c cos u.
TEST(SurfaceStrainTest, ATwistGradientShearsCircumferentialLongitudinal) {
  const Model reference = Sphere(0.8);
  Model twisted = reference;
  const double c = 0.2;
  const KnotGrid& grid = twisted.config.Grid();
  for (int k = 0; k < twisted.config.num_knots; ++k) {
    twisted.state.knots[k][kTau] = c * grid.KnotU(k);
  }
  for (double u : {-0.9, 0.1, 0.4}) {
    const SurfaceStrain e = StrainAt(reference, twisted, u, 0.7);
    const double shear = c * std::cos(u);
    EXPECT_NEAR(e.ecc, 0.0, kTolerance) << u;
    EXPECT_NEAR(e.ell, shear * shear / 2, kTolerance) << u;
    EXPECT_NEAR(e.ecl, shear / 2, kTolerance) << u;
  }
}

TEST(SurfaceStrainTest, RigidMotionStrainsNothing) {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = 0.5;
  values[kA2] = 0.45;
  values[kA3] = 0.9;
  const Model reference = Model::Uniform(ModelConfig::Paper(17), values);
  Model moved = reference;
  moved.state.center = {12.0, -7.0, 30.0};
  const Eigen::Quaterniond q(
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, -0.5).normalized()));
  moved.state.quaternion = {q.w(), q.x(), q.y(), q.z()};
  for (double u : {-1.3, -0.2, 0.5}) {
    const SurfaceStrain e = StrainAt(reference, moved, u, 2.2);
    EXPECT_NEAR(e.ecc, 0.0, kTolerance) << u;
    EXPECT_NEAR(e.ell, 0.0, kTolerance) << u;
    EXPECT_NEAR(e.ecl, 0.0, kTolerance) << u;
  }
}

// A triangle in an oblique plane stretched by 10 % along the
// circumferential direction and rotated: Ecc = (1.1^2 - 1) / 2, whichever
// edges span it.
TEST(SurfaceStrainTest, PlaneStrainOfATriangleIsInItsOwnBasis) {
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized())
          .toRotationMatrix();
  const Eigen::Vector3d c = tilt * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d l = tilt * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d a0 = 3 * c + 1 * l, b0 = -1 * c + 2 * l;
  const Eigen::Matrix3d spin =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.2, -1, 0.4).normalized())
          .toRotationMatrix();
  auto deform = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return spin * (x + 0.1 * x.dot(c) * c);
  };
  const SurfaceStrain e =
      PlaneStrain(a0, b0, deform(a0), deform(b0), c + 0.3 * c.cross(l), l);
  EXPECT_NEAR(e.ecc, (1.1 * 1.1 - 1) / 2, 1e-12);
  EXPECT_NEAR(e.ell, 0.0, 1e-12);
  EXPECT_NEAR(e.ecl, 0.0, 1e-12);
  // e_l on the side of `longitudinal`: flipping it flips the shear only.
  auto shear = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return x + 0.2 * x.dot(l) * c;
  };
  const SurfaceStrain up = PlaneStrain(a0, b0, shear(a0), shear(b0), c, l);
  const SurfaceStrain down = PlaneStrain(a0, b0, shear(a0), shear(b0), c, -l);
  EXPECT_NEAR(up.ecl, 0.1, 1e-12);
  EXPECT_NEAR(down.ecl, -0.1, 1e-12);
  EXPECT_NEAR(up.ell, down.ell, 1e-12);
}

}  // namespace
}  // namespace pfdm
