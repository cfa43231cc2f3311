#include "pfdm/fit/problem/node_normals.h"

#include <cmath>
#include <vector>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A spheroid bent, twisted and turned off the world axes, with a local
// field that NodeNormals must ignore.
Model BentModel() {
  Model model = TestSpheroid(5);
  for (size_t k = 0; k < model.state.knots.size(); ++k) {
    model.state.knots[k][kB0] = 2.0 + 0.5 * k;
    model.state.knots[k][kTau] = 0.05 * k;
  }
  const Eigen::Quaterniond turn(
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, -2, 0.5).normalized()));
  model.state.quaternion = {turn.w(), turn.x(), turn.y(), turn.z()};
  AddTestLocalField(3.0, &model);
  return model;
}

// Each node's normal is a unit vector across both of the global surface's
// tangents there (differences of ModelPoint: central, 1e-6; one-sided at the
// base rim, 1e-4), pointing out of the cavity; at the apex pole it is the
// axis' -z.
TEST(NodeNormalsTest, AreTheGlobalSurfacesNormalsInTheModelFrame) {
  const Model model = BentModel();
  Model global = model;
  global.state.local = LocalField();
  const LocalGrid grid = GridOver(model.config, 7, 12);
  const std::vector<Eigen::Vector3d> normals = NodeNormals(model, grid);
  ASSERT_EQ(normals.size(), static_cast<size_t>(grid.NumNodes()));
  EXPECT_LT((normals[0] - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  const double h = 1e-5;
  for (int row = 1; row < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      const Eigen::Vector3d& n = normals[grid.Node(row, col)];
      const double u = grid.RowU(row);
      const double v = grid.ColV(col);
      const bool rim = row + 1 == grid.rows;
      const Eigen::Vector3d along_u =
          global.ModelPoint(rim ? u : u + h, v) - global.ModelPoint(u - h, v);
      const Eigen::Vector3d along_v =
          global.ModelPoint(u, v + h) - global.ModelPoint(u, v - h);
      EXPECT_NEAR(n.norm(), 1.0, 1e-12);
      EXPECT_LT(std::abs(n.dot(along_u.normalized())), rim ? 1e-4 : 1e-6)
          << row;
      EXPECT_LT(std::abs(n.dot(along_v.normalized())), 1e-6) << row;
      // Outward: away from the ring's centre.
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int j = 0; j < grid.cols; ++j) {
        centre += global.ModelPoint(u, grid.ColV(j)) / grid.cols;
      }
      EXPECT_GT(n.dot(global.ModelPoint(u, v) - centre), 0.0) << row;
    }
  }
}

// Plus moves along the direction only, Minus reads the step back, and both
// Jacobians are the direction (checked against differences).
TEST(NodeNormalsTest, AlongDirectionStaysOnItsLine) {
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.4, 0.87).normalized();
  const AlongDirection manifold(n);
  EXPECT_EQ(manifold.AmbientSize(), 3);
  EXPECT_EQ(manifold.TangentSize(), 1);
  const Eigen::Vector3d x = 1.7 * n;
  const double delta = -0.45;
  Eigen::Vector3d moved;
  ASSERT_TRUE(manifold.Plus(x.data(), &delta, moved.data()));
  EXPECT_LT((moved - (1.7 + delta) * n).norm(), 1e-15);
  double back = 0.0;
  ASSERT_TRUE(manifold.Minus(moved.data(), x.data(), &back));
  EXPECT_NEAR(back, delta, 1e-15);
  Eigen::Vector3d plus_jacobian, minus_jacobian;
  ASSERT_TRUE(manifold.PlusJacobian(x.data(), plus_jacobian.data()));
  ASSERT_TRUE(manifold.MinusJacobian(x.data(), minus_jacobian.data()));
  const double h = 1e-7;
  Eigen::Vector3d ahead;
  manifold.Plus(x.data(), &h, ahead.data());
  EXPECT_LT((plus_jacobian - (ahead - x) / h).norm(), 1e-8);
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d y = x;
    y[c] += h;
    double step = 0.0;
    manifold.Minus(y.data(), x.data(), &step);
    EXPECT_NEAR(minus_jacobian[c], step / h, 1e-8) << c;
  }
}

}  // namespace
}  // namespace pfdm
