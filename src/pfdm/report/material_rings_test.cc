#include "pfdm/report/material_rings.h"

#include <cmath>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

TEST(MaterialRingsTest, RingOfACircleHasItsRadiusAndCentre) {
  Model model = TestSpheroid(9);
  model.state.center = {1.0, -2.0, 3.0};
  const MaterialRing ring = SampleRing(model, 0.3);
  EXPECT_NEAR(MeanRadius(ring), 25.0 * std::cos(0.3), 1e-9);
  EXPECT_TRUE(ring.centroid.isApprox(
      Eigen::Vector3d(1.0, -2.0, 3.0 + 40.0 * std::sin(0.3)), 1e-12));
}

TEST(MaterialRingsTest, AnglesAreRightHandedAboutTheAxis) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(AngleAbout({1, 0, 5}, {0, 1, -3}, z), M_PI / 2, 1e-12);
  EXPECT_NEAR(AngleAbout({1, 0, 0}, {0, 1, 0}, -z), -M_PI / 2, 1e-12);
}

TEST(MaterialRingsTest, TwistReadsAsRotationAndTranslationDoesNot) {
  const Model reference = TestSpheroid(9);
  Model moved = reference;
  for (FunctionValues& knot : moved.state.knots) knot[kTau] = 0.1;
  moved.state.center = {4.0, 5.0, -6.0};
  const double u = 0.2;
  EXPECT_NEAR(MeanRotation(SampleRing(reference, u), SampleRing(moved, u),
                           LongAxis(reference)),
              0.1, 1e-12);
  // A spin of the whole pose about the axis reads the same.
  Model spun = reference;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()));
  spun.state.quaternion = {q.w(), q.x(), q.y(), q.z()};
  EXPECT_NEAR(MeanRotation(SampleRing(reference, u), SampleRing(spun, u),
                           LongAxis(reference)),
              0.1, 1e-12);
}

TEST(MaterialRingsTest, HeightFractionRunsFromApexToRim) {
  const Model model = TestSpheroid(9);
  // sin u is flat at the pole: u is found there to the root of the step.
  EXPECT_NEAR(RingAtHeightFraction(model, 0.0), model.config.u_min, 1e-7);
  EXPECT_NEAR(RingAtHeightFraction(model, 1.0), model.config.u_max, 1e-9);
  const double u = RingAtHeightFraction(model, 0.4);
  const double s_min = std::sin(model.config.u_min);
  EXPECT_NEAR(std::sin(u), s_min + 0.4 * (std::sin(model.config.u_max) - s_min),
              1e-12);
  EXPECT_NEAR(RingHeight(model, u), 40.0 * std::sin(u), 1e-12);
}

}  // namespace
}  // namespace pfdm
