#include "pfdm/fit/problem/local_regularizer.h"

#include <cmath>

#include "ceres/problem.h"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// On a 5 x 8 grid: membrane 4 x 8 along the meridians and 4 x 8 around the
// rings, plate 3 x 8 and 4 x 8, the mixed term 3 x 8, 4 through the pole and
// the pole's mean: 149 differences, and a ring mean per row below the pole
// in orthonormal horizontal directions.  Without stiffness only the pole's
// mean is left.
TEST(LocalRegularizerTest, HasEveryTermOfTheGrid) {
  const Model model = TestSpheroid(5);
  const LocalGrid grid = GridOver(model.config, 5, 8);
  const LocalRegularizer regularizer =
      MakeLocalRegularizer(model, grid, 400, 0.1);
  EXPECT_EQ(regularizer.differences.size(), 149u);
  ASSERT_EQ(regularizer.rings.size(), 4u);
  // sqrt(10 x 400 / 4) / 8 per node.
  EXPECT_NEAR(regularizer.rings[0].scale, std::sqrt(1000.0) / 8, 1e-12);
  for (const RingMean& ring : regularizer.rings) {
    ASSERT_EQ(ring.nodes.size(), 8u);
    for (size_t k = 0; k < ring.nodes.size(); ++k) {
      EXPECT_NEAR(ring.radial[k].norm(), 1.0, 1e-12);
      EXPECT_NEAR(ring.radial[k].dot(ring.tangential[k]), 0.0, 1e-12);
      EXPECT_EQ(ring.radial[k].z(), 0.0);
      EXPECT_EQ(ring.tangential[k].z(), 0.0);
    }
  }
  EXPECT_EQ(MakeLocalRegularizer(model, grid, 400, 0.0).differences.size(), 1u);
}

// As residual blocks: a field moving every node alike costs nothing in
// stiffness, and its ring means cost the means' squares: 1/2 (ring scale x
// nodes)^2 |t|^2 per ring, and the pole's 1/2 w^2 |t|^2.
TEST(LocalRegularizerTest, CostsATranslationItsMeansOnly) {
  const Model model = TestSpheroid(5);
  const LocalGrid grid = GridOver(model.config, 5, 8);
  const LocalRegularizer regularizer =
      MakeLocalRegularizer(model, grid, 400, 0.1);
  LocalField field = LocalField::Zero(grid);
  const Eigen::Vector3d t(0.0, 0.0, 2.0);  // Along the axis: no radial part.
  for (int node = 0; node < grid.NumNodes(); ++node) {
    Eigen::Vector3d::Map(&field.values[3 * node]) = t;
  }
  ceres::Problem problem;
  AddLocalRegularizer(regularizer, &field, &problem);
  EXPECT_EQ(problem.NumResidualBlocks(), 153);
  double cost = 0.0;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr,
                   nullptr);
  const double pole = regularizer.differences.back().sqrt_weight;
  const double ring = regularizer.rings[0].scale * grid.cols;
  const double expected =
      0.5 * (pole * pole + 4 * ring * ring) * t.squaredNorm();
  EXPECT_NEAR(cost, expected, 1e-9 * expected);
  EXPECT_NEAR(RegularizerCost(regularizer, field.values), expected,
              1e-9 * expected);
  // Rings that mean their radial and tangential components alone (a
  // solid's q_w) leave the translation to the pole.
  LocalRegularizer components = regularizer;
  for (RingMean& r : components.rings) r.mean_displacement = false;
  ceres::Problem alone;
  AddLocalRegularizer(components, &field, &alone);
  alone.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr,
                 nullptr);
  const double pole_only = 0.5 * pole * pole * t.squaredNorm();
  EXPECT_NEAR(cost, pole_only, 1e-9 * pole_only);
  EXPECT_NEAR(RegularizerCost(components, field.values), pole_only,
              1e-9 * pole_only);
}

}  // namespace
}  // namespace pfdm
