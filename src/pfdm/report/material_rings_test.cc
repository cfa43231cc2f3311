#include "pfdm/report/material_rings.h"

#include <cmath>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/report/surface_strain.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

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

// The shell's wall, 10 mm, read on a bent, twisted shell with a local
// field: from the ring's batches of walls and its tangents as from the
// material point alone, within 1e-9 mm, and 10 mm where the shell is
// undeformed.
TEST(MaterialRingsTest, WallThicknessFromTheRingsWallsIsTheSame) {
  const Model shell = TestShell(9);
  Model bent = shell;
  for (size_t k = 0; k < bent.state.knots.size(); ++k) {
    bent.state.knots[k][kB0] = 3.0 - 0.4 * k;
    bent.state.knots[k][kTau] = 0.05 * k;
    bent.state.knots[k][kH] = 9.0 + 0.2 * k;
  }
  bent.state.globals[kB0] = 1.0;
  AddTestLocalField(1.5, &bent);
  constexpr int kSamples = 7;
  for (const Model* model :
       std::initializer_list<const Model*>{&shell, &bent}) {
    for (double u : {-1.2, -0.4, 0.0, 0.3}) {
      const RingFunctions ring(*model, u);
      const MaterialRing endo = SampleRing(*model, u, kSamples, -1.0);
      const MaterialRing epi = SampleRing(*model, u, kSamples, 1.0);
      for (int j = 0; j < kSamples; ++j) {
        const double v = -kPi + 2.0 * kPi * (j + 0.5) / kSamples;
        Eigen::Vector3d xu, xv;
        SurfaceTangents(*model, ring, v, &xu, &xv);
        const double expected = WallThickness(*model, u, v);
        EXPECT_NEAR(
            WallThickness(*model, u, v, endo.points[j], epi.points[j], xu, xv),
            expected, 1e-9);
        if (model == &shell) EXPECT_NEAR(expected, 10.0, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace pfdm
