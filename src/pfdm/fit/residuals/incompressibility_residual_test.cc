#include "pfdm/fit/residuals/incompressibility_residual.h"

#include <cmath>
#include <memory>
#include <vector>

#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/model/wall_volume.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// The default phantom's twisted frame as a solid whose wall thickness,
// shift and radii vary from knot to knot, on the superellipsoid model (a0
// and the exponents constant, fitted as globals) so that the globals' and
// the knots' derivatives are both checked; the apex knot sits on the pole.
Model UnevenSolid() {
  Model model = TwistedTestModel();
  model.config.MakeSolid();
  model.config.modes[kA0] = FunctionMode::kConstant;
  for (size_t k = 0; k < model.state.knots.size(); ++k) {
    FunctionValues& knot = model.state.knots[k];
    knot[kH] = 9.0 + std::sin(0.7 * k);
    knot[kWallShift] = 0.5 * std::cos(1.3 * k);
    knot[kA1] *= 1.0 + 0.05 * std::sin(0.9 * k);
  }
  return model;
}

std::vector<double*> Blocks(Model* model) {
  std::vector<double*> blocks = {model->state.globals.data()};
  for (FunctionValues& knot : model->state.knots) blocks.push_back(knot.data());
  return blocks;
}

void ExpectJacobianMatches(Model model, double u_low, double u_high) {
  const IncompressibilityResidual residual(
      model.config, model.UnitExponents(), u_low, u_high, 3.0,
      0.9 * IncompressibilityVolume(model, u_low, u_high), 10.0);
  // Ridders' default first step (1 % of each value) read d r / d a1 0.14 %
  // low, where central differences of 1e-3 to 1e-6 agree with the Jets to
  // 2e-7; a first step of 0.1 % agrees to the last digit.
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-3;
  const std::vector<const ceres::Manifold*> manifolds(
      model.config.num_knots + 1, nullptr);
  ceres::GradientChecker checker(&residual, &manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(Blocks(&model).data(), 1e-7, &results))
      << results.error_log;
  // Not all zero: the wall's functions carry derivatives.
  EXPECT_GT(results.jacobians[5].norm(), 0.0);
  EXPECT_GT(results.jacobians[0].norm(), 0.0);
}

TEST(IncompressibilityResidualTest, ZeroAtTheReferenceAndTheThicknessItLost) {
  Model model = UnevenSolid();
  const double u_low = model.config.u_min, u_high = model.config.u_max;
  const double reference = IncompressibilityVolume(model, u_low, u_high);
  EXPECT_GT(reference, 0.0);
  const IncompressibilityResidual residual(model.config, model.UnitExponents(),
                                           u_low, u_high, 2.0, reference, 10.0);
  double r = 1.0;
  ASSERT_TRUE(residual.Evaluate(Blocks(&model).data(), &r, nullptr));
  EXPECT_NEAR(r, 0.0, 1e-12);
  for (FunctionValues& knot : model.state.knots) knot[kH] *= 1.1;
  ASSERT_TRUE(residual.Evaluate(Blocks(&model).data(), &r, nullptr));
  // sqrt(w) t (V / V_0 - 1), V / V_0 about 1.1 for a wall 10 % thicker.
  const double ratio =
      IncompressibilityVolume(model, u_low, u_high) / reference;
  EXPECT_NEAR(r, 2.0 * 10.0 * (ratio - 1.0), 1e-12);
  EXPECT_NEAR(ratio, 1.1, 0.01);
}

// The residual's 16-gon follows the change of the fine triangulation: frame
// 3 of the phantom against frame 0, both given a wall that thickens by a
// third, within 0.3 points.
TEST(IncompressibilityResidualTest, CoarseRatioFollowsTheFineOne) {
  const Phantom phantom = MakeTestPhantom(1, 5);
  Model ed = phantom.truth[0], es = phantom.truth[3];
  for (Model* model : {&ed, &es}) model->config.MakeSolid();
  for (FunctionValues& knot : ed.state.knots) knot[kH] = 9.0;
  for (FunctionValues& knot : es.state.knots) knot[kH] = 12.0;
  const double u_low = ed.config.u_min, u_high = ed.config.u_max;
  const double coarse = IncompressibilityVolume(es, u_low, u_high) /
                        IncompressibilityVolume(ed, u_low, u_high);
  const double fine = ModelWallVolume(es, u_low, u_high, 8, 128) /
                      ModelWallVolume(ed, u_low, u_high, 8, 128);
  EXPECT_NEAR(coarse, fine, 0.003);
  EXPECT_GT(std::abs(fine - 1.0), 0.01);  // Not a ratio of 1 by accident.
}

// Over the whole model (the apex knot on the pole) and between rings inside
// knot spans.
TEST(IncompressibilityResidualTest, JacobianMatchesNumericDifferences) {
  Model model = UnevenSolid();
  for (const auto& [u_low, u_high] :
       {std::pair(model.config.u_min, model.config.u_max),
        std::pair(-1.234, 0.345)}) {
    SCOPED_TRACE(u_low);
    ExpectJacobianMatches(model, u_low, u_high);
  }
}

}  // namespace
}  // namespace pfdm
