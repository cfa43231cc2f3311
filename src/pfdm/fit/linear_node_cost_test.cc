#include "pfdm/fit/linear_node_cost.h"

#include <cmath>
#include <memory>
#include <vector>

#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/fit/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A posed spheroid with a field on a 5 x 8 grid whose nodes all differ.
Model PosedModelWithField() {
  Model model = TestSpheroid(5);
  model.state.center = {4.0, -7.0, 12.0};
  const double half = 0.4;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  model.state.quaternion = {std::cos(half), std::sin(half) * axis.x(),
                            std::sin(half) * axis.y(),
                            std::sin(half) * axis.z()};
  LocalGrid grid;
  grid.rows = 5;
  grid.cols = 8;
  grid.u_min = model.config.u_min;
  grid.u_max = model.config.u_max;
  model.state.local = LocalField::Zero(grid);
  for (size_t i = 0; i < model.state.local.values.size(); ++i) {
    model.state.local.values[i] = std::sin(1.7 * i) * 2.0;
  }
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

// The residual is the whole model's point minus the data: the shape
// functions of the cost and of Model::WorldPoint are one.
TEST(LinearNodeCostTest, PointResidualIsTheWholeModelMinusData) {
  const Model model = PosedModelWithField();
  Model global = model;
  global.state.local = LocalField();
  const Eigen::Vector3d data(3.0, -1.0, 20.0);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.3, 0.9).normalized();
  for (const Case& c : Cases(model.state.local.grid)) {
    const ShapeWeights shape = ShapeAt(model.state.local.grid, c.u, c.v);
    const std::unique_ptr<ceres::CostFunction> point(MakeLocalPointCost(
        global.WorldPoint(c.u, c.v), model.Rotation(), shape, data));
    const std::unique_ptr<ceres::CostFunction> plane(MakeLocalSurfaceCost(
        global.WorldPoint(c.u, c.v), model.Rotation(), shape, data, normal));
    const std::vector<const double*> parameters = Parameters(model, shape);
    Eigen::Vector3d r;
    double plane_r;
    ASSERT_TRUE(point->Evaluate(parameters.data(), r.data(), nullptr));
    ASSERT_TRUE(plane->Evaluate(parameters.data(), &plane_r, nullptr));
    const Eigen::Vector3d expected = model.WorldPoint(c.u, c.v) - data;
    EXPECT_LT((r - expected).norm(), 1e-10) << c.where;
    EXPECT_NEAR(plane_r, normal.dot(expected), 1e-10) << c.where;
    EXPECT_EQ(shape.count,
              c.u == model.config.u_min || c.u < model.state.local.grid.RowU(1)
                  ? 3
                  : 4)
        << c.where;
  }
}

TEST(LinearNodeCostTest, GradientCheckerAgrees) {
  const Model model = PosedModelWithField();
  Model global = model;
  global.state.local = LocalField();
  const Eigen::Vector3d data(3.0, -1.0, 20.0);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.3, 0.9).normalized();
  ceres::NumericDiffOptions numeric;
  for (const Case& c : Cases(model.state.local.grid)) {
    const ShapeWeights shape = ShapeAt(model.state.local.grid, c.u, c.v);
    const std::vector<const double*> parameters = Parameters(model, shape);
    for (bool plane : {false, true}) {
      const std::unique_ptr<ceres::CostFunction> cost(
          plane ? MakeLocalSurfaceCost(global.WorldPoint(c.u, c.v),
                                       model.Rotation(), shape, data, normal)
                : MakeLocalPointCost(global.WorldPoint(c.u, c.v),
                                     model.Rotation(), shape, data));
      ceres::GradientChecker checker(
          cost.get(),
          static_cast<const std::vector<const ceres::Manifold*>*>(nullptr),
          numeric);
      ceres::GradientChecker::ProbeResults results;
      EXPECT_TRUE(checker.Probe(parameters.data(), 1e-9, &results))
          << c.where << (plane ? " plane" : " point") << ": "
          << results.error_log;
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
  ceres::GradientChecker checker(
      mixed.get(),
      static_cast<const std::vector<const ceres::Manifold*>*>(nullptr),
      numeric);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(nodes, 1e-9, &results)) << results.error_log;
}

}  // namespace
}  // namespace pfdm
