#include "pfdm/model/model.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(ModelConfigTest, PaperSetUpFreesTheLvFunctions) {
  const ModelConfig config = ModelConfig::Paper(17);
  for (int f : {kA1, kA2, kA3, kTau, kB0, kB1, kB2, kB3, kE1o, kE2o}) {
    EXPECT_EQ(config.modes[f], FunctionMode::kFree) << FunctionName(f);
  }
  for (int f : {kA0, kEps1, kEps2, kE3o}) {
    EXPECT_EQ(config.modes[f], FunctionMode::kFixed) << FunctionName(f);
  }
  EXPECT_EQ(config.num_knots, 17);
}

TEST(ModelConfigTest, SuperellipsoidMakesEveryFreeFunctionConstant) {
  const ModelConfig config = ModelConfig::Superellipsoid(17);
  EXPECT_EQ(config.FreeMask(), 0u);
  EXPECT_EQ(config.modes[kTau], FunctionMode::kConstant);
  EXPECT_EQ(config.modes[kA0], FunctionMode::kFixed);
}

TEST(ModelConfigTest, FromNameRejectsUnknownModelsAndTooFewKnots) {
  EXPECT_EQ(ModelConfig::FromName("superellipsoid", 9).name, "superellipsoid");
  EXPECT_THROW(ModelConfig::FromName("cylinder", 17), InputError);
  EXPECT_THROW(ModelConfig::FromName("paper", 1), InputError);
}

TEST(ModelTest, FreeFunctionsInterpolateAndOthersComeFromTheGlobals) {
  Model model = Model::Uniform(ModelConfig::Paper(3), DefaultFunctionValues());
  model.state.knots[1][kA1] = 0.2;
  model.state.knots[2][kA1] = 0.6;
  model.state.globals[kA0] = 7.0;
  model.state.knots[1][kA0] = 99.0;  // Fixed: knots are not read.
  const KnotGrid grid = model.config.Grid();
  const double u = 0.75 * grid.KnotU(1) + 0.25 * grid.KnotU(2);
  EXPECT_NEAR(model.FunctionAt(kA1, u), 0.3, 1e-12);
  EXPECT_EQ(model.FunctionAt(kA0, u), 7.0);
}

// A ring's height along the axis is its points' model z where nothing
// bends or offsets it (the paper's eps1 = 1), a3 varying along u.
TEST(ModelTest, ShapeHeightIsTheRingsModelZ) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 10.0;
  Model model = Model::Uniform(ModelConfig::Paper(5), f);
  for (int k = 0; k < 5; ++k) model.state.knots[k][kA3] = 0.8 + 0.1 * k;
  for (double u : {model.config.u_min, -0.3, 0.0, 0.4, model.config.u_max}) {
    EXPECT_NEAR(model.ShapeHeight(u), model.ModelPoint(u, 0.7).z(), 1e-12) << u;
  }
}

TEST(ModelTest, WorldPointAppliesThePose) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 10.0;
  Model model = Model::Uniform(ModelConfig::Paper(5), f);
  model.state.center = {1.0, 2.0, 3.0};
  // 90 degrees about z: x -> y.
  model.state.quaternion = {std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};
  const Eigen::Vector3d s = model.ModelPoint(0.0, 0.0);
  EXPECT_NEAR(s.x(), 5.0, 1e-12);
  const Eigen::Vector3d x = model.WorldPoint(0.0, 0.0);
  EXPECT_TRUE(x.isApprox(Eigen::Vector3d(1.0, 7.0, 3.0), 1e-12));
  EXPECT_TRUE(model.UnitExponents());
}

// A bent model whose shape functions have the given means (knot k adds
// 0.1 k - 0.1 to each), b0 and b2 varying along u.
Model BentModel(const ModelConfig& config, double b1_mean, double b3_mean) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 40.0;
  f[kB1] = b1_mean, f[kB3] = b3_mean;
  f[kB0] = 6.0, f[kB2] = -4.0;
  Model model = Model::Uniform(config, f);
  for (int k = 0; k < config.num_knots; ++k) {
    model.state.knots[k][kB1] += 0.1 * k - 0.1;
    model.state.knots[k][kB3] += 0.1 * k - 0.1;
    model.state.knots[k][kB0] += 2.0 * k;
    model.state.knots[k][kB2] -= 1.0 * k;
  }
  return model;
}

void ExpectSameSurface(const Model& a, const Model& b) {
  for (double u : {-1.2, -0.5, 0.0, 0.4}) {
    for (double v : {-2.5, -1.0, 0.3, 2.0}) {
      EXPECT_TRUE(a.WorldPoint(u, v).isApprox(b.WorldPoint(u, v), 1e-12));
    }
  }
}

TEST(ModelTest, CanonicalBendingShiftsShapeMeansIntoZeroToTwo) {
  const ModelConfig config = ModelConfig::Paper(3);
  // b1 mean 2.5: shifted by 2, b0 negated.  b3 mean -3.5: shifted by +4,
  // b2 kept.
  const Model original = BentModel(config, 2.5, -3.5);
  Model model = original;
  const BendingShift turns = model.CanonicalizeBending();
  EXPECT_EQ(turns[0], 1.0);
  EXPECT_EQ(turns[1], -2.0);
  Model shifted = original;  // What the fitter does to a frame's path.
  shifted.ShiftBending(turns);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(shifted.state.knots[k], model.state.knots[k]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(model.state.knots[k][kB1], original.state.knots[k][kB1] - 2.0,
                1e-12);
    EXPECT_EQ(model.state.knots[k][kB0], -original.state.knots[k][kB0]);
    EXPECT_NEAR(model.state.knots[k][kB3], original.state.knots[k][kB3] + 4.0,
                1e-12);
    EXPECT_EQ(model.state.knots[k][kB2], original.state.knots[k][kB2]);
  }
  ExpectSameSurface(original, model);
  // Already canonical: untouched, including a mean at the window's start.
  Model canonical = BentModel(config, 1.9, 0.0);
  const ModelState before = canonical.state;
  canonical.CanonicalizeBending();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(canonical.state.knots[k], before.knots[k]);
  }
}

TEST(ModelTest, CanonicalBendingActsOnConstantFunctionsToo) {
  const ModelConfig config = ModelConfig::Superellipsoid(3);
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 40.0;
  f[kB0] = 5.0, f[kB1] = -0.5;
  Model model = Model::Uniform(config, f);
  const Model original = model;
  model.CanonicalizeBending();
  EXPECT_NEAR(model.state.globals[kB1], 1.5, 1e-12);
  EXPECT_EQ(model.state.globals[kB0], -5.0);
  ExpectSameSurface(original, model);
}

}  // namespace
}  // namespace pfdm

namespace pfdm {
namespace {

// Each ring turns by tau at its own u: the twisted model's ring equals the
// untwisted one rotated about the axis by the interpolated tau(u).
TEST(ModelTest, TwistTurnsEachRingByItsOwnTau) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 50.0;
  f[kA1] = 0.4;
  f[kA2] = 0.3;
  const Model straight = Model::Uniform(ModelConfig::Paper(5), f);
  Model twisted = straight;
  for (int k = 0; k < 5; ++k) twisted.state.knots[k][kTau] = 0.05 * k - 0.1;
  for (double u : {-1.2, -0.6, 0.0, 0.4}) {
    const double tau = twisted.FunctionAt(kTau, u);
    for (double v : {-2.0, 0.5, 1.9}) {
      const Eigen::Vector3d p = straight.ModelPoint(u, v);
      const Eigen::Vector3d q = twisted.ModelPoint(u, v);
      EXPECT_NEAR(std::atan2(q.y(), q.x()) - std::atan2(p.y(), p.x()), tau,
                  1e-12);
      EXPECT_NEAR(q.head<2>().norm(), p.head<2>().norm(), 1e-12);
      EXPECT_NEAR(q.z(), p.z(), 1e-12);
    }
  }
}

}  // namespace
}  // namespace pfdm
