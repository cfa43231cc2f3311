#include "pfdm/model/local_field.h"

#include <cmath>
#include <string>
#include <vector>

#include "ceres/jet.h"
#include "gtest/gtest.h"
#include "pfdm/model/model.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

LocalGrid Grid(int rows, int cols) {
  LocalGrid grid;
  grid.rows = rows;
  grid.cols = cols;
  grid.u_min = -kPi / 2;
  grid.u_max = kPi / 6;
  return grid;
}

// Node n holds (n, 2 n, -n) + (0.1, 0, 0): every node differs.
LocalField Numbered(const LocalGrid& grid) {
  LocalField field = LocalField::Zero(grid);
  for (int n = 0; n < grid.NumNodes(); ++n) {
    field.values[3 * n] = n + 0.1;
    field.values[3 * n + 1] = 2.0 * n;
    field.values[3 * n + 2] = -n;
  }
  return field;
}

Eigen::Vector3d NodeValue(const LocalField& field, int node) {
  return Eigen::Vector3d::Map(&field.values[3 * node]);
}

TEST(LocalFieldTest, ParsesTheGridAndNamesTheFlagWhenWrong) {
  const LocalGrid grid = ParseLocalGrid("9x16");
  EXPECT_EQ(grid.rows, 9);
  EXPECT_EQ(grid.cols, 16);
  EXPECT_EQ(Grid(9, 16).NumNodes(), 1 + 8 * 16);
  for (const std::string bad : {"9", "9x", "x16", "2x16", "9x3", "41x16",
                                "9x73", "9x16x2", "9 x16", "-9x16", ""}) {
    try {
      ParseLocalGrid(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--local_grid must be NUxNV with 3 to 40 rows and 4 to 72 "
                "columns, got '" +
                    bad + "'");
    }
  }
}

TEST(LocalFieldTest, NodesTakeTheirOwnValue) {
  const LocalGrid grid = Grid(5, 8);
  const LocalField field = Numbered(grid);
  for (int row = 0; row < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      const double u = grid.RowU(row), v = grid.ColV(col);
      EXPECT_LT(
          (field.Displacement(u, v) - NodeValue(field, grid.Node(row, col)))
              .norm(),
          1e-12)
          << row << " " << col;
      const ShapeWeights shape = ShapeAt(grid, u, v);
      double sum = 0.0;
      for (int k = 0; k < shape.count; ++k) sum += shape.weight[k];
      EXPECT_NEAR(sum, 1.0, 1e-15);
    }
  }
}

TEST(LocalFieldTest, ElementsAreBilinearAndThePoleRowBlendsToOneNode) {
  const LocalGrid grid = Grid(5, 8);
  const LocalField field = Numbered(grid);
  // Inside element (row 2, col 3) at s = 0.25, t = 0.6.
  const double du = grid.RowU(1) - grid.RowU(0), dv = 2 * kPi / 8;
  double u = grid.RowU(2) + 0.25 * du, v = grid.ColV(3) + 0.6 * dv;
  ShapeWeights shape = ShapeAt(grid, u, v);
  ASSERT_EQ(shape.count, 4);
  EXPECT_EQ(shape.node[0], grid.Node(2, 3));
  EXPECT_NEAR(shape.weight[0], 0.75 * 0.4, 1e-12);
  EXPECT_EQ(shape.node[3], grid.Node(3, 4));
  EXPECT_NEAR(shape.weight[3], 0.25 * 0.6, 1e-12);
  const Eigen::Vector3d expected =
      0.75 * (0.4 * NodeValue(field, grid.Node(2, 3)) +
              0.6 * NodeValue(field, grid.Node(2, 4))) +
      0.25 * (0.4 * NodeValue(field, grid.Node(3, 3)) +
              0.6 * NodeValue(field, grid.Node(3, 4)));
  EXPECT_LT((field.Displacement(u, v) - expected).norm(), 1e-12);
  // The pole row: the pole and two nodes of row 1.
  u = grid.u_min + 0.5 * du;
  shape = ShapeAt(grid, u, v);
  ASSERT_EQ(shape.count, 3);
  EXPECT_EQ(shape.node[0], 0);
  EXPECT_NEAR(shape.weight[0], 0.5, 1e-12);
  // Every v meets at the pole: the surface stays closed.
  for (double pole_v : {-kPi, -1.0, 0.3, 3.0}) {
    EXPECT_LT(
        (field.Displacement(grid.u_min, pole_v) - NodeValue(field, 0)).norm(),
        1e-12);
  }
}

TEST(LocalFieldTest, PeriodicAcrossTheSeam) {
  const LocalGrid grid = Grid(5, 8);
  const LocalField field = Numbered(grid);
  const double u = 0.1;
  // The last element runs from v = 3 pi / 4 to pi = -pi, column 7 to 0.
  const ShapeWeights shape = ShapeAt(grid, u, kPi - 1e-9);
  ASSERT_EQ(shape.count, 4);
  EXPECT_EQ(shape.node[0], grid.Node(3, 7));
  EXPECT_EQ(shape.node[1], grid.Node(3, 0));
  EXPECT_NEAR(shape.weight[1], (1.0 - 0.1 / grid.RowU(4)) * 1.0, 1e-6);
  EXPECT_LT(
      (field.Displacement(u, kPi - 1e-9) - field.Displacement(u, -kPi + 1e-9))
          .norm(),
      1e-6);
  EXPECT_LT((field.Displacement(u, kPi) - field.Displacement(u, -kPi)).norm(),
            1e-12);
  EXPECT_LT(
      (field.Displacement(u, kPi + 0.2) - field.Displacement(u, -kPi + 0.2))
          .norm(),
      1e-12);
}

TEST(LocalFieldTest, JetDerivativesMatchDifferences) {
  const LocalGrid grid = Grid(5, 8);
  const LocalField field = Numbered(grid);
  using Jet2 = ceres::Jet<double, 2>;
  for (auto [u, v] :
       {std::pair{-1.4, 0.2}, std::pair{0.05, -3.0}, std::pair{-0.4, 2.9}}) {
    const Eigen::Matrix<Jet2, 3, 1> d =
        LocalDisplacement(field, Jet2(u, 0), Jet2(v, 1));
    constexpr double h = 1e-7;
    const Eigen::Vector3d du =
        (field.Displacement(u + h, v) - field.Displacement(u - h, v)) / (2 * h);
    const Eigen::Vector3d dv =
        (field.Displacement(u, v + h) - field.Displacement(u, v - h)) / (2 * h);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(d[i].a, field.Displacement(u, v)[i], 1e-12);
      EXPECT_NEAR(d[i].v[0], du[i], 1e-5 * (1 + std::abs(du[i])));
      EXPECT_NEAR(d[i].v[1], dv[i], 1e-5 * (1 + std::abs(dv[i])));
    }
  }
}

// p = s + d in the model frame: the world point moves by R d.
TEST(LocalFieldTest, ModelPointsCarryTheField) {
  Model model = TestSpheroid(5);
  model.state.center = {1.0, 2.0, 3.0};
  model.state.quaternion = {std::cos(0.3), std::sin(0.3), 0.0, 0.0};
  const Eigen::Vector3d before = model.WorldPoint(-0.3, 1.1);
  LocalGrid grid = Grid(5, 8);
  model.state.local = Numbered(grid);
  const Eigen::Vector3d d = model.state.local.Displacement(-0.3, 1.1);
  EXPECT_LT(
      (model.ModelPoint(-0.3, 1.1) - TestSpheroid(5).ModelPoint(-0.3, 1.1) - d)
          .norm(),
      1e-12);
  EXPECT_LT(
      (model.WorldPoint(-0.3, 1.1) - before - model.Rotation() * d).norm(),
      1e-12);
}

// d(u, v, w) = S (q + w q_w): the slope's field, measured as the change
// from w = 0 to w = 1 (and linear: half that at w = 0.5, its negative at
// w = -1), in doubles and Jets alike; w = 0 is the field without it.
TEST(LocalFieldTest, ATransmuralFieldIsLinearInW) {
  const LocalGrid grid = Grid(5, 8);
  LocalField field = Numbered(grid);
  const LocalField plain = field;
  field.slope.assign(field.values.size(), 0.0);
  for (size_t i = 0; i < field.slope.size(); ++i) {
    field.slope[i] = 0.3 * std::cos(0.7 * i);
  }
  LocalField slope_only = LocalField::Zero(grid);
  slope_only.values = field.slope;
  EXPECT_TRUE(field.transmural());
  EXPECT_FALSE(plain.transmural());
  for (double u : {-kPi / 2, -0.9, 0.2}) {
    for (double v : {-kPi, 0.4, 2.9}) {
      const Eigen::Vector3d mid = field.Displacement(u, v);
      EXPECT_LT((mid - plain.Displacement(u, v)).norm(), 1e-12);
      const Eigen::Vector3d per_w = slope_only.Displacement(u, v);
      EXPECT_LT((field.Displacement(u, v, 1.0) - mid - per_w).norm(), 1e-12);
      EXPECT_LT((field.Displacement(u, v, 0.5) - mid - 0.5 * per_w).norm(),
                1e-12);
      EXPECT_LT((field.Displacement(u, v, -1.0) - mid + per_w).norm(), 1e-12);
      using Jet2 = ceres::Jet<double, 2>;
      const Eigen::Matrix<Jet2, 3, 1> jet =
          LocalDisplacement(field, Jet2(u, 0), Jet2(v, 1), -0.4);
      const Eigen::Vector3d value = field.Displacement(u, v, -0.4);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(jet[k].a, value[k], 1e-12);
    }
  }
}

// k(w) = clamp(3 w, -1, 1) - w: zero at the walls and the mid-wall, odd,
// linear between the knees at +-1/3; the field adds k(w) q_k to the line
// q + w q_w, in doubles and Jets alike.
TEST(LocalFieldTest, AKinkBendsTheProfileBetweenTheWalls) {
  EXPECT_EQ(TransmuralKink(-1.0), 0.0);
  EXPECT_EQ(TransmuralKink(0.0), 0.0);
  EXPECT_EQ(TransmuralKink(1.0), 0.0);
  EXPECT_NEAR(TransmuralKink(1.0 / 3.0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(TransmuralKink(-0.2), -0.4, 1e-15);
  EXPECT_NEAR(TransmuralKink(0.6), 0.4, 1e-15);
  const LocalGrid grid = Grid(5, 8);
  LocalField field = LocalField::Zero(grid, /*transmural=*/true);
  LocalField line = field, kink_only = LocalField::Zero(grid);
  for (size_t i = 0; i < field.values.size(); ++i) {
    field.values[i] = line.values[i] = std::sin(0.3 * i);
    field.slope[i] = line.slope[i] = 0.3 * std::cos(0.7 * i);
    field.kink[i] = kink_only.values[i] = 0.8 * std::cos(1.1 * i);
  }
  for (double u : {-kPi / 2, -0.9, 0.2}) {
    for (double v : {-kPi, 0.4, 2.9}) {
      for (double w : {-1.0, -0.5, -0.2, 0.0, 1.0 / 3.0, 0.7, 1.0}) {
        const Eigen::Vector3d expected =
            line.Displacement(u, v, w) +
            TransmuralKink(w) * kink_only.Displacement(u, v);
        EXPECT_LT((field.Displacement(u, v, w) - expected).norm(), 1e-12);
        using Jet2 = ceres::Jet<double, 2>;
        const Eigen::Matrix<Jet2, 3, 1> jet =
            LocalDisplacement(field, Jet2(u, 0), Jet2(v, 1), w);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(jet[k].a, expected[k], 1e-12);
      }
    }
  }
}

// The noise draws perturb q, q_w and q_k as one vector: values first, then
// the slope, then the kink; a shorter vector moves q alone.
TEST(LocalFieldTest, CoefficientsAreTheValuesThenTheSlopeThenTheKink) {
  const LocalGrid grid = Grid(4, 6);
  LocalField field = LocalField::Zero(grid, /*transmural=*/true);
  ASSERT_EQ(field.slope.size(), field.values.size());
  ASSERT_EQ(field.kink.size(), field.values.size());
  std::vector<double> change(3 * field.values.size());
  for (size_t i = 0; i < change.size(); ++i) change[i] = i + 1.0;
  field.AddCoefficients(change);
  EXPECT_EQ(field.Coefficients(), change);
  LocalField copy = LocalField::Zero(grid, /*transmural=*/true);
  copy.SetCoefficients(change.data());
  EXPECT_EQ(copy.Coefficients(), change);
  EXPECT_EQ(field.slope.front(), field.values.size() + 1.0);
  EXPECT_EQ(field.kink.front(), 2.0 * field.values.size() + 1.0);
  LocalField plain = LocalField::Zero(grid);
  plain.AddCoefficients(change);
  EXPECT_EQ(plain.Coefficients().size(), plain.values.size());
  EXPECT_EQ(plain.values.back(), static_cast<double>(plain.values.size()));
}

}  // namespace
}  // namespace pfdm
