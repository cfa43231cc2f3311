#include "pfdm/phantom/lv_motion.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr double kRadians = kPi / 180.0;

TEST(LvPhantomMotionTest, DesignedValues) {
  const LvDeformation design;
  EXPECT_NEAR(DesignedRadialContraction(design, 0.0, 0.0), 0.24, 1e-12);
  EXPECT_NEAR(DesignedRadialContraction(design, 0.5, 0.0), 0.22, 1e-12);
  EXPECT_NEAR(DesignedRadialContraction(design, 1.0, 0.0), 0.20, 1e-12);
  EXPECT_NEAR(DesignedRadialContraction(design, 0.5, -1.0), 0.30, 1e-12);
  EXPECT_NEAR(DesignedRadialContraction(design, 0.5, 1.0), 0.065, 1e-12);
  EXPECT_NEAR(DesignedRotationDeg(design, 0.0), -10.0, 1e-12);
  EXPECT_NEAR(DesignedRotationDeg(design, 1.0), 3.0, 1e-12);
  EXPECT_NEAR(DesignedRotationDeg(design, 0.5), -3.5, 1e-12);
}

TEST(LvPhantomMotionTest, MovesAMaterialPointAsDesigned) {
  const LvShape shape;
  const LvDeformation design;
  // The apex pole stays put.
  EXPECT_NEAR(DeformedBodyPoint(
                  design, MaterialPointAt(shape, Eigen::Vector3d::Zero()), 1.0)
                  .norm(),
              0.0, 1e-12);
  const double h = 0.6, phi = 0.4;
  const Eigen::Vector3d x =
      shape.Position(shape.NuAtHeight(h * shape.base_z(), -1.0), phi, -1.0);
  const LvMaterialPoint point = MaterialPointAt(shape, x);
  EXPECT_NEAR(point.w, -1.0, 1e-9);
  EXPECT_NEAR(point.h, h, 1e-12);
  const double p = 0.8;
  const Eigen::Vector3d y = DeformedBodyPoint(design, point, p);
  EXPECT_NEAR(y.z(), (1.0 - 0.17 * p) * x.z(), 1e-12);
  EXPECT_NEAR(std::hypot(y.x(), y.y()),
              (1.0 - (0.24 - 0.04 * h + 0.08) * p) * point.radius, 1e-9);
  EXPECT_NEAR(std::atan2(y.y(), y.x()) - phi, (-10.0 + 13.0 * h) * p * kRadians,
              1e-12);
}

TEST(LvPhantomMotionTest, LesionCoversMidSegmentTwoOnly) {
  LvDeformation design;
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0), 1.0, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.45, 82.0), 1.0, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.5, 70.0), 0.5, 1e-12);  // Mid-edge.
  EXPECT_NEAR(LesionWeight(design, 1.0 / 3.0 + 0.05, 90.0), 0.5, 1e-12);
  // Moved to another centre, across the seam at 0 = 360 degrees.
  LvDeformation moved = design;
  moved.lesion_center_deg = 10.0;
  EXPECT_NEAR(LesionWeight(moved, 0.5, 10.0), 1.0, 1e-12);
  EXPECT_NEAR(LesionWeight(moved, 0.5, 350.0), 0.5, 1e-12);
  EXPECT_EQ(LesionWeight(moved, 0.5, 90.0), 0.0);
  for (double lambda : {59.0, 121.0, 270.0, -90.0}) {
    EXPECT_EQ(LesionWeight(design, 0.5, lambda), 0.0) << lambda;
  }
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0 + 360.0), 1.0, 1e-12);
  for (double h : {0.33, 0.67, 0.1, 0.9}) {
    EXPECT_EQ(LesionWeight(design, h, 90.0), 0.0) << h;
  }
  // Counter-clockwise about +z from -x, longitude 90 degrees is -y.
  const LvShape shape;
  design.lesion = true;
  const double z = 0.5 * shape.base_z();
  for (double phi : {-kPi / 2, kPi / 2}) {
    const Eigen::Vector3d x =
        shape.Position(shape.NuAtHeight(z, 0.0), phi, 0.0);
    const LvMaterialPoint point = MaterialPointAt(shape, x);
    const double c =
        1.0 - std::hypot(DeformedBodyPoint(design, point, 1.0).x(),
                         DeformedBodyPoint(design, point, 1.0).y()) /
                  point.radius;
    EXPECT_NEAR(c, phi < 0 ? 0.3 * 0.22 : 0.22, 1e-9) << phi;
  }
}

// A subendocardial lesion (outer w 0): whole at the endocardium, half at
// the mid-wall (its edge's middle), none at the epicardium; transmural
// (the default) whole at every depth.
TEST(LvPhantomMotionTest, ASubendocardialLesionHoldsTheInnerHalf) {
  LvDeformation design;
  for (double w : {-1.0, 0.0, 1.0}) {
    EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, w), 1.0, 1e-12) << w;
  }
  design.lesion_outer_w = 0.0;
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, -1.0), 1.0, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, -0.2), 1.0, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, 0.2), 0.0, 1e-12);
  EXPECT_NEAR(LesionWeight(design, 0.5, 90.0, 1.0), 0.0, 1e-12);
}

TEST(LvPhantomMotionTest, ScenarioFrames) {
  LvFrameMotion last = ScenarioMotion(LvKinematics::kSystole, 4, 5, true);
  EXPECT_EQ(last.progress, 1.0);
  EXPECT_NEAR(last.rigid.axial_shift_mm, 4.0, 1e-12);
  EXPECT_NEAR(last.rigid.lateral_shift_mm, 2.0, 1e-12);
  EXPECT_NEAR(last.rigid.tilt_deg, 2.0, 1e-12);
  EXPECT_EQ(
      ScenarioMotion(LvKinematics::kSystole, 4, 5, false).rigid.axial_shift_mm,
      0.0);
  const LvFrameMotion first =
      ScenarioMotion(LvKinematics::kSystole, 0, 5, true);
  EXPECT_EQ(first.progress, 0.0);
  EXPECT_EQ(first.rigid.axial_shift_mm, 0.0);
  EXPECT_EQ(first.rigid.lateral_shift_mm, 0.0);
  EXPECT_EQ(first.rigid.tilt_deg, 0.0);

  EXPECT_NEAR(ScenarioMotion(LvKinematics::kCycle, 4, 9, true).progress, 1.0,
              1e-15);
  last = ScenarioMotion(LvKinematics::kCycle, 8, 9, true);
  EXPECT_EQ(last.progress, 0.0);
  EXPECT_EQ(last.rigid.axial_shift_mm, 0.0);
  EXPECT_EQ(last.rigid.lateral_shift_mm, 0.0);
  EXPECT_EQ(last.rigid.tilt_deg, 0.0);

  EXPECT_EQ(ScenarioMotion(LvKinematics::kRigidAxial, 4, 5, true)
                .rigid.axial_shift_mm,
            8.0);
  EXPECT_EQ(ScenarioMotion(LvKinematics::kRigidLateral, 2, 5, true)
                .rigid.lateral_shift_mm,
            2.5);
  EXPECT_EQ(ScenarioMotion(LvKinematics::kRigidTilt, 4, 5, true).rigid.tilt_deg,
            8.0);
  const LvFrameMotion spin =
      ScenarioMotion(LvKinematics::kRigidSpin, 4, 5, true);
  EXPECT_EQ(spin.rigid.spin_deg, 10.0);
  EXPECT_EQ(spin.progress, 0.0);
  EXPECT_EQ(spin.rigid.axial_shift_mm, 0.0);
  EXPECT_EQ(ScenarioMotion(LvKinematics::kStatic, 4, 5, true).progress, 0.0);
}

TEST(LvPhantomMotionTest, RigidMotionPivotsOnTheLvCentre) {
  const LvShape shape;
  const Eigen::Vector3d centre(0.0, 0.0, 0.5 * shape.base_z());
  LvRigidMotion tilt;
  tilt.tilt_deg = 8.0;
  EXPECT_NEAR((RigidBodyMotion(shape, tilt) * centre - centre).norm(), 0.0,
              1e-12);
  const Eigen::Vector3d apex_moved =
      RigidBodyMotion(shape, tilt) * Eigen::Vector3d::Zero();
  EXPECT_NEAR(std::acos((centre - apex_moved).normalized().z()), 8.0 * kRadians,
              1e-9);
  LvRigidMotion spin;
  spin.spin_deg = 10.0;
  const Eigen::Isometry3d turn = RigidBodyMotion(shape, spin);
  EXPECT_NEAR(
      (turn * Eigen::Vector3d(0, 0, 30) - Eigen::Vector3d(0, 0, 30)).norm(),
      0.0, 1e-12);
  EXPECT_NEAR(std::atan2((turn * Eigen::Vector3d::UnitX()).y(),
                         (turn * Eigen::Vector3d::UnitX()).x()),
              10.0 * kRadians, 1e-12);
  LvRigidMotion shift;
  shift.axial_shift_mm = 8.0;
  shift.lateral_shift_mm = 5.0;
  EXPECT_NEAR((RigidBodyMotion(shape, shift).translation() -
               Eigen::Vector3d(5.0 * kLvLateral.x(), 5.0 * kLvLateral.y(), 8.0))
                  .norm(),
              0.0, 1e-12);
  EXPECT_NEAR(kLvLateral.norm(), 1.0, 1e-12);
  EXPECT_NEAR(kLvTiltAxis.norm(), 1.0, 1e-12);
  EXPECT_NEAR(kLvTiltAxis.dot(kLvLateral), 0.0, 1e-12);
}

TEST(LvPhantomMotionTest, NamesRoundTrip) {
  for (const char* name : {"systole", "cycle", "rigid-axial", "rigid-lateral",
                           "rigid-tilt", "rigid-spin", "static"}) {
    LvKinematics kinematics;
    ASSERT_TRUE(ParseLvKinematics(name, &kinematics)) << name;
    EXPECT_EQ(LvKinematicsName(kinematics), name);
  }
  LvKinematics kinematics;
  EXPECT_FALSE(ParseLvKinematics("diastole", &kinematics));
  EXPECT_EQ(DefaultFrameCount(LvKinematics::kCycle), 9);
  EXPECT_EQ(DefaultFrameCount(LvKinematics::kRigidTilt), 5);
}

}  // namespace
}  // namespace pfdm
