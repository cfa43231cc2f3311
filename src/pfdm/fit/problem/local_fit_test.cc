#include "pfdm/fit/problem/local_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/problem/node_normals.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A field that no ring mean carries (radial cos 3v, axial sin 2v, zero at
// the pole), up to 2 mm, on the spheroid posed obliquely.
struct Truth {
  Model global;
  Model whole;
};

Truth MakeTruth(const LocalGrid& grid) {
  Truth truth{TestSpheroid(5), {}};
  truth.global.state.center = {10.0, -5.0, 30.0};
  truth.global.state.quaternion = {std::cos(0.25), 0.0, std::sin(0.25), 0.0};
  truth.whole = truth.global;
  LocalField field = LocalField::Zero(grid);
  for (int row = 1; row < grid.rows; ++row) {
    const double amplitude = 2.0 * std::sin(kPi * row / (grid.rows - 1) / 1.2);
    for (int col = 0; col < grid.cols; ++col) {
      const double v = grid.ColV(col);
      double* q = &field.values[3 * grid.Node(row, col)];
      q[0] = amplitude * std::cos(3 * v) * std::cos(v);
      q[1] = amplitude * std::cos(3 * v) * std::sin(v);
      q[2] = 0.5 * amplitude * std::sin(2 * v);
    }
  }
  truth.whole.state.local = field;
  return truth;
}

// 1,500 points of the whole model without noise, spread evenly in sin u
// over most of its length, and their material points.
void SampleWholeModel(const Truth& truth, unsigned seed,
                      std::vector<Eigen::Vector3d>* points,
                      std::vector<MaterialPoint>* material) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 1500; ++i) {
    const double u = std::asin(-1.0 + 1.5 * unit(random));
    const double v = -kPi + 2 * kPi * unit(random);
    material->push_back({u, v});
    points->push_back(truth.whole.WorldPoint(u, v));
  }
}

// Tracked points of the whole model, without noise, and the fitted field's
// largest error over a dense grid, for each solver: the linear problem has
// one minimum, and with little stiffness it is the truth.
TEST(LocalFitTest, EverySolverRecoversAFieldWithoutRingMeans) {
  const LocalGrid grid = GridOver(TestSpheroid(5).config, 7, 12);
  const Truth truth = MakeTruth(grid);
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  SampleWholeModel(truth, 3, &points, &material);
  const std::vector<bool> sliding(points.size(), false);
  for (const char* solver : {"direct", "damped", "integrator"}) {
    FitOptions options;
    options.solver.kind = SolverFromName(solver);
    options.local.rows = grid.rows;
    options.local.cols = grid.cols;
    options.local.stiffness = 1e-5;
    Model fitted = truth.global;
    const SolverReport report =
        FitLocalField(points, material, sliding, options, &fitted);
    EXPECT_TRUE(report.usable) << solver;
    double worst = 0.0;
    for (int i = 0; i <= 40; ++i) {
      const double u = grid.u_min + (grid.u_max - grid.u_min) * i / 40;
      for (int j = 0; j < 60; ++j) {
        const double v = -kPi + 2 * kPi * j / 60;
        worst = std::max(
            worst,
            (fitted.WorldPoint(u, v) - truth.whole.WorldPoint(u, v)).norm());
      }
    }
    std::printf("%s: worst %.4f mm, %d iterations\n", solver, worst,
                report.iterations);
    EXPECT_LT(worst, 0.02) << solver;
    // The global part is held.
    EXPECT_EQ(fitted.state.knots, truth.global.state.knots);
    EXPECT_EQ(fitted.state.center, truth.global.state.center);
  }
}

// The largest distance (mm) between the two models over a dense grid of
// the field's u range.
double WorstDistance(const Model& a, const Model& b, const LocalGrid& grid) {
  double worst = 0.0;
  for (int i = 0; i <= 40; ++i) {
    const double u = grid.u_min + (grid.u_max - grid.u_min) * i / 40;
    for (int j = 0; j < 60; ++j) {
      const double v = -kPi + 2 * kPi * j / 60;
      worst = std::max(worst, (a.WorldPoint(u, v) - b.WorldPoint(u, v)).norm());
    }
  }
  return worst;
}

// The largest part of any node's value across its normal (mm).
double LargestAcross(const LocalField& field,
                     const std::vector<Eigen::Vector3d>& normals) {
  double largest = 0.0;
  for (size_t k = 0; k < normals.size(); ++k) {
    const Eigen::Map<const Eigen::Vector3d> q(&field.values[3 * k]);
    largest = std::max(largest, (q - normals[k] * normals[k].dot(q)).norm());
  }
  return largest;
}

// Points of the whole model that all slide (contours alone): every solver
// moves each node along the global surface's normal only (the Ceres
// solvers through AlongDirection), to the same field as the direct solve
// (the damped and integrator's stopping rules: 0.01 mm), and the field
// still takes up the truth's part along the normal (the points' largest
// gap along it 5x less than to the global model).  One tracked point among them
// frees the nodes again.
TEST(LocalFitTest, ContoursAloneMoveTheNodesAlongTheNormal) {
  const LocalGrid grid = GridOver(TestSpheroid(5).config, 7, 12);
  const Truth truth = MakeTruth(grid);
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  SampleWholeModel(truth, 5, &points, &material);
  const std::vector<Eigen::Vector3d> normals = NodeNormals(truth.global, grid);
  std::vector<bool> sliding(points.size(), true);
  FitOptions options;
  options.local.rows = grid.rows;
  options.local.cols = grid.cols;
  options.local.stiffness = 1e-3;
  Model direct = truth.global;
  ASSERT_TRUE(
      FitLocalField(points, material, sliding, options, &direct).usable);
  EXPECT_LT(LargestAcross(direct.state.local, normals), 1e-12);
  const std::vector<Eigen::Vector3d> point_normals =
      SurfaceNormals(truth.global, material);
  const auto largest_gap = [&](const Model& model) {
    double largest = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d x = model.WorldPoint(material[i].u, material[i].v);
      largest =
          std::max(largest, std::abs(point_normals[i].dot(x - points[i])));
    }
    return largest;
  };
  EXPECT_LT(largest_gap(direct), 0.2 * largest_gap(truth.global));
  for (const char* solver : {"damped", "integrator"}) {
    options.solver.kind = SolverFromName(solver);
    Model fitted = truth.global;
    ASSERT_TRUE(
        FitLocalField(points, material, sliding, options, &fitted).usable);
    EXPECT_LT(LargestAcross(fitted.state.local, normals), 1e-12) << solver;
    EXPECT_LT(WorstDistance(fitted, direct, grid), 0.01) << solver;
  }
  options.solver.kind = SolverKind::kDirect;
  sliding[0] = false;
  Model tracked = truth.global;
  ASSERT_TRUE(
      FitLocalField(points, material, sliding, options, &tracked).usable);
  EXPECT_GT(LargestAcross(tracked.state.local, normals), 0.1);
}

// The points above with 0.2 mm of noise and 5 % of them moved 5-10 mm in a
// random direction: least squares bends the field toward them, a robust
// loss (reweighted until the weights settle) leaves it about where the
// points without outliers put it.
TEST(LocalFitTest, ARobustLossLeavesOutliersOut) {
  const LocalGrid grid = GridOver(TestSpheroid(5).config, 7, 12);
  const Truth truth = MakeTruth(grid);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<Eigen::Vector3d> points, inliers;
  std::vector<MaterialPoint> material;
  std::vector<bool> outlier;
  for (int i = 0; i < 1500; ++i) {
    const double u = std::asin(-1.0 + 1.5 * unit(random));
    const double v = -kPi + 2 * kPi * unit(random);
    material.push_back({u, v});
    Eigen::Vector3d x =
        truth.whole.WorldPoint(u, v) +
        Eigen::Vector3d(noise(random), noise(random), noise(random));
    inliers.push_back(x);
    outlier.push_back(i % 20 == 0);
    if (outlier.back()) {
      const Eigen::Vector3d direction(noise(random), noise(random),
                                      noise(random));
      x += (5.0 + 5.0 * unit(random)) * direction.normalized();
    }
    points.push_back(x);
  }
  const std::vector<bool> sliding(points.size(), false);
  FitOptions options;
  options.local.rows = grid.rows;
  options.local.cols = grid.cols;
  options.local.stiffness = 1e-3;
  Model clean = truth.global, plain = truth.global;
  FitLocalField(inliers, material, sliding, options, &clean);
  FitLocalField(points, material, sliding, options, &plain);
  const double clean_error = WorstDistance(clean, truth.whole, grid);
  const double plain_error = WorstDistance(plain, truth.whole, grid);
  std::printf("worst: without outliers %.3f mm, least squares %.3f mm\n",
              clean_error, plain_error);
  EXPECT_GT(plain_error, 1.5);
  for (const char* loss : {"huber", "cauchy"}) {
    options.loss = loss;
    options.loss_scale_mm = 0.5;
    Model robust = truth.global;
    const SolverReport report =
        FitLocalField(points, material, sliding, options, &robust);
    EXPECT_TRUE(report.usable) << loss;
    const double robust_error = WorstDistance(robust, truth.whole, grid);
    std::printf("%s: worst %.3f mm, %d solves\n", loss, robust_error,
                report.iterations);
    // Huber 0.310 mm, against 0.278 without the outliers.
    EXPECT_LT(robust_error, 1.2 * clean_error) << loss;
    EXPECT_GT(report.iterations, 1) << loss;  // Reweighted.
  }
}

// A field of ring means alone (every ring moved radially out by 1 mm and
// along the axis by 1 mm) is the global functions' job: the local field
// takes almost none of it.
TEST(LocalFitTest, RingMeansStayWithTheGlobalFunctions) {
  const LocalGrid grid = GridOver(TestSpheroid(5).config, 7, 12);
  Model global = TestSpheroid(5);
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  for (int i = 0; i < 30; ++i) {
    const double u = std::asin(-0.95 + 1.4 * i / 29.0);
    for (int j = 0; j < 40; ++j) {
      const double v = -kPi + 2 * kPi * (j + 0.5) / 40;
      material.push_back({u, v});
      points.push_back(global.WorldPoint(u, v) +
                       Eigen::Vector3d(std::cos(v), std::sin(v), 1.0));
    }
  }
  FitOptions options;
  options.local.rows = grid.rows;
  options.local.cols = grid.cols;
  Model fitted = global;
  FitLocalField(points, material, std::vector<bool>(points.size(), false),
                options, &fitted);
  // The penalty (10 x a ring's points) leaves about 1/11 of a ring's mean
  // to the field where nothing else pulls: 0.04-0.12 mm of the 1 mm, more
  // where a row's elements hold more points.  (100 x would leave 0.014 mm
  // but cost the integrator 10 times the steps; in a fit the global
  // functions have taken the ring means before the field is fitted.)
  double largest = 0.0;
  for (int row = 1; row < grid.rows; ++row) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double radial = 0.0;
    for (int col = 0; col < grid.cols; ++col) {
      const Eigen::Vector3d q = Eigen::Vector3d::Map(
          &fitted.state.local.values[3 * grid.Node(row, col)]);
      mean += q / grid.cols;
      const double v = grid.ColV(col);
      radial += (std::cos(v) * q.x() + std::sin(v) * q.y()) / grid.cols;
    }
    std::printf("row %d: mean radial %.4f, axial %.4f mm\n", row, radial,
                mean.z());
    largest = std::max({largest, std::abs(radial), std::abs(mean.z())});
  }
  EXPECT_LT(largest, 0.15);
}

// A solid (the shell, 10 mm wall) whose field varies through the wall: q
// as MakeTruth's, q_w radial cos 2v and axial cos v (no ring mean).
// A shell whose field varies through the wall; `bent`: also a ring-wide
// shift of the epicardium against the endocardium in q_w (which q's ring
// means would hold) and a kink q_k between the walls, as tags through the
// wall see and both walls' contours cannot.
Model TransmuralShell(const LocalGrid& grid, bool bent = false) {
  Model model = TestShell(5);
  model.state.center = {10.0, -5.0, 30.0};
  model.state.quaternion = {std::cos(0.25), 0.0, std::sin(0.25), 0.0};
  LocalField field = LocalField::Zero(grid, /*transmural=*/true);
  for (int row = 1; row < grid.rows; ++row) {
    const double amplitude = std::sin(kPi * row / (grid.rows - 1) / 1.2);
    for (int col = 0; col < grid.cols; ++col) {
      const double v = grid.ColV(col);
      const int at = 3 * grid.Node(row, col);
      field.values[at] = 2.0 * amplitude * std::cos(3 * v) * std::cos(v);
      field.values[at + 1] = 2.0 * amplitude * std::cos(3 * v) * std::sin(v);
      field.slope[at] = amplitude * std::cos(2 * v) * std::cos(v);
      field.slope[at + 1] = amplitude * std::cos(2 * v) * std::sin(v);
      field.slope[at + 2] = 0.5 * amplitude * std::cos(v);
      if (!bent) continue;
      field.slope[at] += 0.4 * amplitude;
      field.kink[at] = 1.5 * amplitude * std::sin(2 * v) * std::cos(v);
      field.kink[at + 1] = 1.5 * amplitude * std::sin(2 * v) * std::sin(v);
    }
  }
  model.state.local = field;
  return model;
}

// The largest distance (mm) between the models' layers at `depths` over a
// dense grid.
double WorstThroughTheWall(const Model& a, const Model& b,
                           const LocalGrid& grid,
                           const std::vector<double>& depths = {-1.0, 0.0,
                                                                1.0}) {
  double worst = 0.0;
  for (double w : depths) {
    for (int i = 0; i <= 30; ++i) {
      const double u = grid.u_min + (grid.u_max - grid.u_min) * i / 30;
      for (int j = 0; j < 48; ++j) {
        const double v = -kPi + 2 * kPi * j / 48;
        worst = std::max(
            worst, (a.WorldPoint(u, v, w) - b.WorldPoint(u, v, w)).norm());
      }
    }
  }
  return worst;
}

struct WallPoints {
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
};

// Noise-free points of `truth` at random (u, v), w uniform through the wall
// (tags) or on its two surfaces alone (both walls' contours).
WallPoints SampleTheWall(const Model& truth, bool surfaces_only) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  WallPoints out;
  for (int i = 0; i < 3000; ++i) {
    const double u = std::asin(-1.0 + 1.5 * unit(random));
    const double v = -kPi + 2 * kPi * unit(random);
    const double w =
        surfaces_only ? (i % 2 == 0 ? -1.0 : 1.0) : -1.0 + 2.0 * unit(random);
    out.material.push_back({u, v, w});
    out.points.push_back(truth.WorldPoint(u, v, w));
  }
  return out;
}

// Tags through the wall: the three parts (q, q_w at each tag's w and the
// kink q_k) come back with every solver, in a few passes, at the walls and
// the layers between (w = +-1/3, +-0.6), a ring-wide shift included;
// both surfaces alone (w = +-1, as both walls' contours) are the
// endocardium's and the epicardium's fields, apart: one pass, the direct
// solver's two solves.
TEST(LocalFitTest, ATransmuralFieldComesBackThroughTheWall) {
  const LocalGrid grid = GridOver(TestShell(5).config, 7, 12);
  for (bool surfaces_only : {false, true}) {
    const Model truth = TransmuralShell(grid, /*bent=*/!surfaces_only);
    Model global = truth;
    global.state.local = LocalField();
    const WallPoints data = SampleTheWall(truth, surfaces_only);
    const std::vector<bool> sliding(data.points.size(), false);
    const std::vector<double> depths =
        surfaces_only ? std::vector<double>{-1.0, 0.0, 1.0}
                      : std::vector<double>{-1.0,      -0.6, -1.0 / 3.0, 0.0,
                                            1.0 / 3.0, 0.6,  1.0};
    for (const char* solver : {"direct", "damped"}) {
      FitOptions options;
      options.solver.kind = SolverFromName(solver);
      options.local.rows = grid.rows;
      options.local.cols = grid.cols;
      options.local.stiffness = 1e-5;
      options.local.transmural = true;
      Model fitted = global;
      const SolverReport report =
          FitLocalField(data.points, data.material, sliding, options, &fitted);
      ASSERT_TRUE(report.usable) << solver;
      ASSERT_TRUE(fitted.state.local.transmural());
      const double worst = WorstThroughTheWall(fitted, truth, grid, depths);
      std::printf("%s, %s: worst %.4f mm, %d iterations\n",
                  surfaces_only ? "surfaces" : "through the wall", solver,
                  worst, report.iterations);
      EXPECT_LT(worst, 0.03) << solver;
      if (surfaces_only && std::string(solver) == "direct") {
        EXPECT_EQ(report.iterations, 2);
      }
    }
  }
  const Model truth = TransmuralShell(grid);
  Model global = truth;
  global.state.local = LocalField();
  // Without the option the same solid's field moves every layer alike.
  FitOptions options;
  options.local.rows = grid.rows;
  options.local.cols = grid.cols;
  Model fitted = global;
  const WallPoints data = SampleTheWall(truth, false);
  FitLocalField(data.points, data.material,
                std::vector<bool>(data.points.size(), false), options, &fitted);
  EXPECT_FALSE(fitted.state.local.transmural());
  EXPECT_GT(WorstThroughTheWall(fitted, truth, grid), 0.5);
}

}  // namespace
}  // namespace pfdm
