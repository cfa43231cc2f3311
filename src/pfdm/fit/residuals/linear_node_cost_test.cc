#include "pfdm/fit/residuals/linear_node_cost.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A posed spheroid with a field on a 5 x 8 grid whose nodes all differ.
Model PosedModelWithField() {
  Model model = TestSpheroid(5);
  model.state.center = {4.0, -7.0, 12.0};
  const double half = 0.4;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  model.state.quaternion = {std::cos(half), std::sin(half) * axis.x(),
                            std::sin(half) * axis.y(),
                            std::sin(half) * axis.z()};
  AddTestLocalField(2.0, &model);
  return model;
}

struct Case {
  const char* where;
  double u, v;
};

// The pole row, the seam at v = +-pi, element corners and edges, inside.
std::vector<Case> Cases(const LocalGrid& grid) {
  const double du = grid.RowU(1) - grid.RowU(0);
  return {{"pole row", grid.u_min + 0.3 * du, 0.7},
          {"pole", grid.u_min, -2.0},
          {"seam -pi", grid.RowU(2) + 0.4 * du, -kPi},
          {"seam below pi", grid.RowU(3) + 0.5 * du, kPi - 1e-3},
          {"corner", grid.RowU(2), grid.ColV(3)},
          {"edge", grid.RowU(3), grid.ColV(5) + 0.2},
          {"base rim", grid.u_max, 1.0},
          {"inside", grid.RowU(1) + 0.8 * du, 2.1}};
}

// The cost's nodes' values, in the order of the shape's nodes.
std::vector<const double*> Parameters(const Model& model,
                                      const ShapeWeights& shape) {
  std::vector<const double*> parameters;
  for (int k = 0; k < shape.count; ++k) {
    parameters.push_back(&model.state.local.values[3 * shape.node[k]]);
  }
  return parameters;
}

// The point and plane costs of a data point at (u, v), on the model
// without its field.
struct Costs {
  std::unique_ptr<ceres::CostFunction> point, plane;
};
const Eigen::Vector3d kData(3.0, -1.0, 20.0);
const Eigen::Vector3d kNormal = Eigen::Vector3d(0.2, -0.3, 0.9).normalized();

Costs CostsAt(const Model& model, const ShapeWeights& shape, double u,
              double v) {
  Model global = model;
  global.state.local = LocalField();
  const Eigen::Vector3d x = global.WorldPoint(u, v);
  return {std::unique_ptr<ceres::CostFunction>(
              MakeLocalPointCost(x, model.Rotation(), shape, kData)),
          std::unique_ptr<ceres::CostFunction>(MakeLocalSurfaceCost(
              x, model.Rotation(), shape, kData, kNormal))};
}

// ceres::GradientChecker's report on `cost` at `parameters`, "" if it
// agrees.
std::string GradientError(const ceres::CostFunction* cost,
                          const double* const* parameters) {
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  ceres::GradientChecker checker(cost, no_manifolds,
                                 ceres::NumericDiffOptions());
  ceres::GradientChecker::ProbeResults results;
  return checker.Probe(parameters, 1e-9, &results) ? "" : results.error_log;
}

// The residual is the whole model's point minus the data: the shape
// functions of the cost and of Model::WorldPoint are one.
TEST(LinearNodeCostTest, PointResidualIsTheWholeModelMinusData) {
  const Model model = PosedModelWithField();
  for (const Case& c : Cases(model.state.local.grid)) {
    const ShapeWeights shape = ShapeAt(model.state.local.grid, c.u, c.v);
    const Costs costs = CostsAt(model, shape, c.u, c.v);
    const std::vector<const double*> parameters = Parameters(model, shape);
    Eigen::Vector3d r;
    double plane_r;
    ASSERT_TRUE(costs.point->Evaluate(parameters.data(), r.data(), nullptr));
    ASSERT_TRUE(costs.plane->Evaluate(parameters.data(), &plane_r, nullptr));
    const Eigen::Vector3d expected = model.WorldPoint(c.u, c.v) - kData;
    EXPECT_LT((r - expected).norm(), 1e-10) << c.where;
    EXPECT_NEAR(plane_r, kNormal.dot(expected), 1e-10) << c.where;
    EXPECT_EQ(shape.count,
              c.u == model.config.u_min || c.u < model.state.local.grid.RowU(1)
                  ? 3
                  : 4)
        << c.where;
  }
}

TEST(LinearNodeCostTest, GradientCheckerAgrees) {
  const Model model = PosedModelWithField();
  for (const Case& c : Cases(model.state.local.grid)) {
    const ShapeWeights shape = ShapeAt(model.state.local.grid, c.u, c.v);
    const std::vector<const double*> parameters = Parameters(model, shape);
    const Costs costs = CostsAt(model, shape, c.u, c.v);
    for (bool plane : {false, true}) {
      EXPECT_EQ(GradientError((plane ? costs.plane : costs.point).get(),
                              parameters.data()),
                "")
          << c.where << (plane ? " plane" : " point");
    }
  }
  const double q[4][3] = {{1, 2, 3}, {-1, 0.5, 2}, {0, 0, 1}, {4, -2, 0}};
  const double* nodes[4] = {q[0], q[1], q[2], q[3]};
  const std::unique_ptr<ceres::CostFunction> mixed(
      MakeNodeDifferenceCost(3.0, {1.0, -1.0, -1.0, 1.0}));
  double r[3];
  ASSERT_TRUE(mixed->Evaluate(nodes, r, nullptr));
  EXPECT_NEAR(r[0], 3.0 * (1 + 1 - 0 + 4), 1e-12);
  EXPECT_NEAR(r[1], 3.0 * (2 - 0.5 - 0 - 2), 1e-12);
  EXPECT_EQ(GradientError(mixed.get(), nodes), "");
}

}  // namespace
}  // namespace pfdm
