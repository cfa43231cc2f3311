#include "pfdm/fit/problem/local_direct.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "Eigen/Geometry"
#include "ceres/problem.h"
#include "gtest/gtest.h"
#include "pfdm/fit/problem/node_normals.h"
#include "pfdm/fit/residuals/linear_node_cost.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Random points on a 7 x 12 grid of the spheroid, each with a global point,
// a data point up to 3 mm off it and (with `weighted`) a loss weight in
// (0.1, 1], under an oblique rotation.
struct Case {
  Model model = TestSpheroid(5);
  LocalGrid grid;
  Eigen::Matrix3d rotation;
  std::vector<Eigen::Vector3d> globals, points;
  std::vector<Eigen::Vector3d> normals;  // World frame; zero: none.
  LocalDirectData data;
};

Case MakeCase(int num_points, bool weighted, unsigned seed,
              bool sliding = false) {
  Case c;
  c.grid = GridOver(c.model.config, 7, 12);
  c.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())
                   .toRotationMatrix();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < num_points; ++i) {
    const double u =
        c.grid.u_min + (c.grid.u_max - c.grid.u_min) * unit(random);
    const double v = -kPi + 2 * kPi * unit(random);
    const Eigen::Vector3d global = c.model.WorldPoint(u, v);
    const Eigen::Vector3d off(unit(random) - 0.5, unit(random) - 0.5,
                              unit(random) - 0.5);
    c.globals.push_back(global);
    c.points.push_back(global + 6.0 * off);
    c.data.shapes.push_back(ShapeAt(c.grid, u, v));
    c.data.offsets.push_back(c.rotation.transpose() *
                             (c.globals.back() - c.points.back()));
    if (weighted) c.data.weights.push_back(0.1 + 0.9 * unit(random));
    // Every other point on a contour: a random normal.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    if (sliding && i % 2 == 0) {
      normal = Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5,
                               unit(random) - 0.5)
                   .normalized();
    }
    c.normals.push_back(normal);
    c.data.normals.push_back(c.rotation.transpose() * normal);
  }
  return c;
}

// The same least squares through Ceres: each point's rows, the
// regularizer's blocks, one undamped Gauss-Newton step.
LocalField CeresSolve(const Case& c, const LocalRegularizer& regularizer,
                      SolverReport* report) {
  LocalField field = LocalField::Zero(c.grid);
  ceres::Problem problem;
  for (size_t i = 0; i < c.points.size(); ++i) {
    const ShapeWeights& shape = c.data.shapes[i];
    const bool plane = !c.normals[i].isZero(0.0);
    LocalRows rows =
        LocalPointRows(c.globals[i], c.rotation, shape, c.points[i],
                       plane ? &c.normals[i] : nullptr);
    if (!c.data.weights.empty()) rows *= std::sqrt(c.data.weights[i]);
    std::vector<double*> nodes;
    for (int k = 0; k < shape.count; ++k) {
      nodes.push_back(&field.values[3 * shape.node[k]]);
    }
    problem.AddResidualBlock(MakeLinearNodeCost(rows), nullptr, nodes);
  }
  AddLocalRegularizer(regularizer, &field, &problem);
  for (size_t k = 0; k < regularizer.node_normals.size(); ++k) {
    problem.SetManifold(&field.values[3 * k],
                        new AlongDirection(regularizer.node_normals[k]));
  }
  SolverOptions options;
  options.linear = true;
  *report = SolveDirect(&problem, options);
  return field;
}

double MaxDifference(const LocalField& a, const LocalField& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.values.size(); ++i) {
    worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
  }
  return worst;
}

// Without Ceres, the same field (1e-9 mm: round-off on displacements of
// millimetres) and the same costs before and after, weighted or not, with
// points on contours (the whole A) or without (K and Woodbury).
TEST(LocalDirectTest, SolvesAsCeresDoes) {
  for (int variant = 0; variant < 4; ++variant) {
    const bool weighted = variant % 2 == 1;
    const Case c = MakeCase(600, weighted, 5, /*sliding=*/variant >= 2);
    const LocalRegularizer regularizer =
        MakeLocalRegularizer(c.model, c.grid, 600, 0.05);
    SolverReport ceres_report;
    const LocalField expected = CeresSolve(c, regularizer, &ceres_report);
    ASSERT_TRUE(ceres_report.usable);
    LocalField field = LocalField::Zero(c.grid);
    LocalDirectSolver solver;
    SolverReport report;
    ASSERT_TRUE(solver.Solve(c.data, regularizer, &field, &report));
    EXPECT_LT(MaxDifference(field, expected), 1e-9) << variant;
    EXPECT_EQ(solver.factorizations(), variant >= 2 ? 0 : 1);
    // The field moves millimetres: the comparison is not between zeros.
    EXPECT_GT(*std::max_element(field.values.begin(), field.values.end()), 0.1);
    ASSERT_EQ(report.trace.size(), 2u);
    EXPECT_NEAR(report.trace[0].cost, ceres_report.trace.front().cost,
                1e-9 * ceres_report.trace.front().cost);
    EXPECT_NEAR(report.trace[1].cost, ceres_report.trace.back().cost,
                1e-9 * ceres_report.trace.back().cost);
    // At the minimum the gradient vanishes against its start.
    EXPECT_LT(report.trace[1].gradient_norm,
              1e-10 * report.trace[0].gradient_norm);
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.iterations, 1);
  }
}

// Rings that mean their radial and tangential components alone (a
// solid's q_w, local_fit.cc): the direct solve is Ceres' within 1e-9 mm,
// with points pulling whole and along normals, and it differs from the
// solve with the rings' mean displacement by more than 0.01 mm.
TEST(LocalDirectTest, SolvesRingsOfComponentsAloneAsCeresDoes) {
  for (bool sliding : {false, true}) {
    const Case c = MakeCase(600, /*weighted=*/false, 5, sliding);
    const LocalRegularizer full =
        MakeLocalRegularizer(c.model, c.grid, 600, 0.05);
    LocalRegularizer regularizer = full;
    for (RingMean& ring : regularizer.rings) ring.mean_displacement = false;
    SolverReport ceres_report;
    const LocalField expected = CeresSolve(c, regularizer, &ceres_report);
    ASSERT_TRUE(ceres_report.usable);
    LocalDirectSolver solver;
    LocalField field = LocalField::Zero(c.grid), with_means = field;
    SolverReport report;
    ASSERT_TRUE(solver.Solve(c.data, regularizer, &field, &report));
    EXPECT_LT(MaxDifference(field, expected), 1e-9) << sliding;
    ASSERT_TRUE(solver.Solve(c.data, full, &with_means, &report));
    EXPECT_GT(MaxDifference(field, with_means), 0.01) << sliding;
  }
}

// Every point on a contour and each node held to the global surface's
// normal (a frame of contours alone): the direct solve restricted to one
// unknown per node is Ceres' on the AlongDirection manifold within 1e-9 mm,
// every node lies on its normal's line, and the restriction matters (the
// free field moves nodes along the surface by more than 0.1 mm).
TEST(LocalDirectTest, HoldsNodesToTheirNormalsAsCeresDoes) {
  Case c = MakeCase(600, /*weighted=*/true, 9, /*sliding=*/true);
  for (size_t i = 0; i < c.points.size(); ++i) {
    if (!c.normals[i].isZero(0.0)) continue;
    c.normals[i] = Eigen::Vector3d(1, 1, -1).normalized();
    c.data.normals[i] = c.rotation.transpose() * c.normals[i];
  }
  LocalRegularizer regularizer =
      MakeLocalRegularizer(c.model, c.grid, 600, 0.05);
  LocalDirectSolver solver;
  LocalField free_field = LocalField::Zero(c.grid);
  SolverReport report;
  ASSERT_TRUE(solver.Solve(c.data, regularizer, &free_field, &report));
  regularizer.node_normals = NodeNormals(c.model, c.grid);
  SolverReport ceres_report;
  const LocalField expected = CeresSolve(c, regularizer, &ceres_report);
  ASSERT_TRUE(ceres_report.usable);
  LocalField field = LocalField::Zero(c.grid);
  ASSERT_TRUE(solver.Solve(c.data, regularizer, &field, &report));
  EXPECT_LT(MaxDifference(field, expected), 1e-9);
  EXPECT_NEAR(report.trace[1].cost, ceres_report.trace.back().cost,
              1e-9 * ceres_report.trace.back().cost);
  EXPECT_LT(report.trace[1].gradient_norm,
            1e-10 * report.trace[0].gradient_norm);
  double largest = 0.0, free_across = 0.0;
  for (int k = 0; k < c.grid.NumNodes(); ++k) {
    const Eigen::Vector3d& n = regularizer.node_normals[k];
    const Eigen::Map<const Eigen::Vector3d> q(&field.values[3 * k]);
    const Eigen::Map<const Eigen::Vector3d> free_q(&free_field.values[3 * k]);
    EXPECT_LT((q - n * n.dot(q)).norm(), 1e-12) << k;
    largest = std::max(largest, q.norm());
    free_across = std::max(free_across, (free_q - n * n.dot(free_q)).norm());
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_GT(free_across, 0.1);
}

// A second frame with the same points and weights but other data and
// another global shape (ring directions): K is reused, and the field agrees
// with a fresh solver's within 1e-9 mm.  Other weights factorize again.
TEST(LocalDirectTest, ReusesKOnlyWhenItIsTheSame) {
  const Case first = MakeCase(500, true, 7);
  Case second = MakeCase(500, true, 7);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (size_t i = 0; i < second.points.size(); ++i) {
    second.points[i] +=
        Eigen::Vector3d(noise(random), noise(random), noise(random));
    second.data.offsets[i] =
        second.rotation.transpose() * (second.globals[i] - second.points[i]);
  }
  Model other_shape = second.model;
  for (FunctionValues& knot : other_shape.state.knots) knot[kA1] *= 1.3;
  other_shape.state.globals[kA1] *= 1.3;
  LocalDirectSolver kept;
  LocalField field = LocalField::Zero(first.grid);
  SolverReport report;
  ASSERT_TRUE(kept.Solve(
      first.data, MakeLocalRegularizer(first.model, first.grid, 500, 0.05),
      &field, &report));
  const LocalRegularizer regularizer =
      MakeLocalRegularizer(other_shape, second.grid, 500, 0.05);
  // The rings' directions did change with the shape.
  const LocalRegularizer before =
      MakeLocalRegularizer(first.model, first.grid, 500, 0.05);
  EXPECT_GT((regularizer.rings[2].radial[1] - before.rings[2].radial[1]).norm(),
            0.01);
  ASSERT_TRUE(kept.Solve(second.data, regularizer, &field, &report));
  EXPECT_EQ(kept.factorizations(), 1);
  LocalDirectSolver fresh;
  LocalField fresh_field = LocalField::Zero(second.grid);
  ASSERT_TRUE(fresh.Solve(second.data, regularizer, &fresh_field, &report));
  EXPECT_LT(MaxDifference(field, fresh_field), 1e-9);
  SolverReport ceres_report;
  EXPECT_LT(
      MaxDifference(field, CeresSolve(second, regularizer, &ceres_report)),
      1e-9);

  second.data.weights[3] *= 0.5;
  ASSERT_TRUE(kept.Solve(second.data, regularizer, &field, &report));
  EXPECT_EQ(kept.factorizations(), 2);
  EXPECT_LT(
      MaxDifference(field, CeresSolve(second, regularizer, &ceres_report)),
      1e-9);
}

// Contour points (the whole A): a solver that keeps the regularizer's part
// of A from an earlier solve (the same regularizer, other points and
// normals, as a frame's next contour round) or has to drop it (another
// global shape's ring directions, as the next frame) solves as Ceres does,
// within 1e-9 mm.
TEST(LocalDirectTest, KeepsTheStiffnessOnlyWhileTheRegularizerStays) {
  const Case first = MakeCase(500, true, 7, /*sliding=*/true);
  const Case second = MakeCase(500, true, 8, /*sliding=*/true);
  const LocalRegularizer regularizer =
      MakeLocalRegularizer(first.model, first.grid, 500, 0.05);
  Model other_shape = second.model;
  for (FunctionValues& knot : other_shape.state.knots) knot[kA1] *= 1.3;
  other_shape.state.globals[kA1] *= 1.3;
  const LocalRegularizer other =
      MakeLocalRegularizer(other_shape, second.grid, 500, 0.05);
  LocalDirectSolver kept;
  LocalField field = LocalField::Zero(first.grid);
  SolverReport report, ceres_report;
  ASSERT_TRUE(kept.Solve(first.data, regularizer, &field, &report));
  for (const LocalRegularizer* next : {&regularizer, &other}) {
    field = LocalField::Zero(second.grid);
    ASSERT_TRUE(kept.Solve(second.data, *next, &field, &report));
    const LocalField expected = CeresSolve(second, *next, &ceres_report);
    EXPECT_LT(MaxDifference(field, expected), 1e-9);
    EXPECT_GT(*std::max_element(field.values.begin(), field.values.end()), 0.1);
  }
}

// A node no point and no stiffness holds: K is singular, the solver says
// so and leaves the field alone (the caller then asks Ceres).
TEST(LocalDirectTest, RefusesASingularK) {
  Case c = MakeCase(3, false, 2);
  const LocalRegularizer regularizer =
      MakeLocalRegularizer(c.model, c.grid, 3, 0.0);
  LocalField field = LocalField::Zero(c.grid);
  field.values[7] = 1.5;
  LocalDirectSolver solver;
  SolverReport report;
  EXPECT_FALSE(solver.Solve(c.data, regularizer, &field, &report));
  EXPECT_EQ(field.values[7], 1.5);
  EXPECT_EQ(solver.factorizations(), 0);
}

}  // namespace
}  // namespace pfdm
