#include "pfdm/fit/correspondence/correspondence.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "ceres/jet.h"
#include "gtest/gtest.h"
#include "pfdm/fit/stages/initialization.h"
#include "pfdm/model/local_field.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A phantom of num_points tags over 5 frames and frame t's positions.
std::vector<Eigen::Vector3d> PhantomPositions(int num_points, int t,
                                              Phantom* phantom) {
  PhantomOptions options;
  options.num_points = num_points;
  options.num_frames = 5;
  *phantom = MakePhantom(options);
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : phantom->points.frames[t].points) {
    points.push_back(p.position);
  }
  return points;
}

TEST(CorrespondenceTest, FindsTheMaterialPointOfPointsOffTheSurface) {
  const Model model = TwistedTestModel();
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> expected;
  for (double u = -1.3; u < 0.5; u += 0.2) {
    for (double v = -3.0; v < 3.1; v += 0.7) {
      expected.push_back({u, v});
      points.push_back(model.WorldPoint(u, v) +
                       0.8 * SurfaceNormal(model, u, v));
    }
  }
  const std::vector<MaterialPoint> found = ClosestMaterialPoints(model, points);
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(found[i].u, expected[i].u, 1e-5);
    EXPECT_NEAR(std::remainder(found[i].v - expected[i].v, 2 * M_PI), 0.0,
                1e-5);
    EXPECT_NEAR((model.WorldPoint(found[i].u, found[i].v) - points[i]).norm(),
                0.8, 1e-6);
  }
}

TEST(CorrespondenceTest, PointsNearTheApexFindTheirMeridian) {
  const Model model = TwistedTestModel();
  for (double v : {-2.5, -0.4, 1.2, 2.9}) {
    const double u = -M_PI / 2 + 0.02;
    const Eigen::Vector3d point = model.WorldPoint(u, v);
    const MaterialPoint found = ClosestMaterialPoints(model, {point})[0];
    // Within the search's stopping step of the point (a wrong meridian
    // would be millimetres off).
    EXPECT_LT((model.WorldPoint(found.u, found.v) - point).norm(),
              CorrespondenceOptions().step_tolerance_mm)
        << v;
  }
}

// A material point's height is its world point's component along the
// model's axis 3, measured a second way: one at a time, against the axis
// through the model's centre; the apex pole lies lowest.
TEST(CorrespondenceTest, AxialHeightsAreAlongTheModelsAxis) {
  const Model model = TwistedTestModel();
  const std::vector<MaterialPoint> material = {{-M_PI / 2, 0.0, 0.0},
                                               {-0.7, 1.0, 0.0},
                                               {0.3, -2.0, 0.0},
                                               {0.5, 3.0, 0.0}};
  const std::vector<double> heights = AxialHeights(model, material);
  ASSERT_EQ(heights.size(), material.size());
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const Eigen::Vector3d center(model.state.center.data());
  for (size_t i = 0; i < material.size(); ++i) {
    const Eigen::Vector3d x = model.WorldPoint(material[i].u, material[i].v);
    EXPECT_NEAR(heights[i] - axis.dot(center), (x - center).dot(axis), 1e-9)
        << i;
  }
  EXPECT_EQ(std::min_element(heights.begin(), heights.end()), heights.begin());
  EXPECT_TRUE(AxialHeights(model, {}).empty());
}

TEST(CorrespondenceTest, ResidualsAreModelPointMinusDataPoint) {
  const Model model = TwistedTestModel();
  const std::vector<MaterialPoint> material = {{-0.7, 1.0, 0.0},
                                               {0.3, -2.0, 0.0}};
  const std::vector<Eigen::Vector3d> points = {{1.0, 2.0, 3.0},
                                               {-4.0, 0.5, 7.0}};
  const std::vector<Eigen::Vector3d> residuals =
      Residuals(model, points, material);
  ASSERT_EQ(residuals.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d x = model.WorldPoint(material[i].u, material[i].v);
    EXPECT_NEAR((residuals[i] - (x - points[i])).norm(), 0.0, 1e-12) << i;
  }
  EXPECT_TRUE(Residuals(model, {}, {}).empty());
}

TEST(CorrespondenceTest, NormalIsUnitAndOrthogonalToTheSurface) {
  const Model model = TwistedTestModel();
  for (double u : {-M_PI / 2, -1.0, 0.1, 0.5}) {  // Not at knots.
    const Eigen::Vector3d n = SurfaceNormal(model, u, 0.4);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    const Eigen::Vector3d du =
        model.WorldPoint(u + 1e-6, 0.4) - model.WorldPoint(u - 1e-6, 0.4);
    EXPECT_NEAR(n.dot(du.normalized()), 0.0, 1e-4) << u;
    // Outward: away from the point across the same ring.
    const Eigen::Vector3d across =
        model.WorldPoint(u, 0.4 - M_PI) - model.WorldPoint(u, 0.4);
    if (u > -M_PI / 2) EXPECT_LT(n.dot(across.normalized()), -0.5) << u;
  }
  // At the apex pole the normal is the axis pointing away from the base.
  EXPECT_TRUE(SurfaceNormal(model, -M_PI / 2, 0.0)
                  .isApprox(-model.Rotation().col(2), 1e-9));
}

// The batch gives SurfaceNormal and the model points, the pole included.
TEST(CorrespondenceTest, SurfaceNormalsMatchTheOneAtATimeNormal) {
  const Model model = TwistedTestModel();
  std::vector<MaterialPoint> material;
  for (double u : {-M_PI / 2, -1.0, 0.1, 0.5}) {
    for (double v : {-3.0, 0.4, 2.2}) material.push_back({u, v, 0.0});
  }
  std::vector<Eigen::Vector3d> points;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, material, &points);
  ASSERT_EQ(normals.size(), material.size());
  ASSERT_EQ(points.size(), material.size());
  for (size_t i = 0; i < material.size(); ++i) {
    const MaterialPoint& m = material[i];
    EXPECT_TRUE(normals[i].isApprox(SurfaceNormal(model, m.u, m.v), 1e-15))
        << i;
    EXPECT_LT((points[i] - model.WorldPoint(m.u, m.v)).norm(), 1e-11) << i;
  }
}

// Sliding points below the rim get SurfaceNormal; the others, and a
// sliding point on the rim, zero.
TEST(CorrespondenceTest, SlidingNormalsAreThoseOfSlidingPointsBelowTheRim) {
  const Model model = TwistedTestModel();
  const double u_max = model.config.u_max;
  const std::vector<MaterialPoint> material = {
      {-1.0, 0.4, 0.0}, {0.2, -2.0, 0.0}, {u_max, 1.0, 0.0}, {0.1, 3.0, 0.0}};
  const std::vector<Eigen::Vector3d> normals =
      SlidingNormals(model, material, {true, false, true, true});
  ASSERT_EQ(normals.size(), 4u);
  EXPECT_EQ(normals[0], SurfaceNormal(model, -1.0, 0.4));
  EXPECT_EQ(normals[1], Eigen::Vector3d::Zero());
  EXPECT_EQ(normals[2], Eigen::Vector3d::Zero());
  EXPECT_EQ(normals[3], SurfaceNormal(model, 0.1, 3.0));
}

// The search hands its last evaluation's normal to the solve after it,
// which then need not evaluate the surface again: it must be SurfaceNormal
// at the material point found, bit for bit, from the grid or from a hint,
// on the mid-wall (closed-form derivatives) and off it in a solid (Jets).
TEST(CorrespondenceTest, SearchGivesTheSurfaceNormalsOfItsMaterialPoints) {
  Phantom phantom;
  const std::vector<Eigen::Vector3d> points =
      PhantomPositions(400, 3, &phantom);
  Model solid = phantom.truth[3];
  solid.config.MakeSolid();
  solid.state.globals[kH] = 8.0;
  for (FunctionValues& knot : solid.state.knots) knot[kH] = 8.0;
  for (const Model& model : {phantom.truth[3], solid}) {
    CorrespondenceOptions options;
    if (model.config.Solid()) options.surfaces.assign(points.size(), 0.6);
    std::vector<Eigen::Vector3d> found, normals;
    const std::vector<MaterialPoint> cold =
        ClosestMaterialPoints(model, points, options, &found, &normals);
    options.hints = cold;
    for (MaterialPoint& hint : options.hints) hint.u -= 0.01;
    std::vector<Eigen::Vector3d> warm_found, warm_normals;
    const std::vector<MaterialPoint> warm = ClosestMaterialPoints(
        model, points, options, &warm_found, &warm_normals);
    ASSERT_EQ(normals.size(), points.size());
    ASSERT_EQ(warm_normals.size(), points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(normals[i],
                SurfaceNormal(model, cold[i].u, cold[i].v, cold[i].w))
          << i;
      EXPECT_EQ(warm_normals[i],
                SurfaceNormal(model, warm[i].u, warm[i].v, warm[i].w))
          << i;
      EXPECT_NEAR(normals[i].norm(), 1.0, 1e-12) << i;
    }
  }
}

// The search stops once a step moves the model point by less than
// step_tolerance_mm; running every step instead (tolerance 0, the search as
// it was before the early stop) must find the same material points, on the
// truth and on a frame-0 start far from the data, and threads must not
// change a bit of the result.
TEST(CorrespondenceTest, EarlyStopAndThreadsFindTheSameMaterialPoints) {
  Phantom phantom;
  const std::vector<Eigen::Vector3d> points =
      PhantomPositions(3000, 3, &phantom);
  const Model start = InitializeModel(phantom.truth[3].config, points, {});
  for (const Model& model : {phantom.truth[3], start}) {
    CorrespondenceOptions exhaustive;
    exhaustive.step_tolerance_mm = 0.0;
    const std::vector<MaterialPoint> reference =
        ClosestMaterialPoints(model, points, exhaustive);
    const std::vector<MaterialPoint> found =
        ClosestMaterialPoints(model, points);
    CorrespondenceOptions threaded;
    threaded.num_threads = 2;
    const std::vector<MaterialPoint> found_threaded =
        ClosestMaterialPoints(model, points, threaded);
    double worst_mm = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      // Three stopping steps (3e-4 mm) on the model: a six-hundredth of
      // the correspondence rounds' tolerance (0.05 mm), a two-thousandth of
      // the data's noise (0.5 mm).
      const Eigen::Vector3d x_found = model.WorldPoint(found[i].u, found[i].v);
      const Eigen::Vector3d x_reference =
          model.WorldPoint(reference[i].u, reference[i].v);
      const double offset = (x_found - x_reference).norm();
      worst_mm = std::max(worst_mm, offset);
      // Squared distances to the data agree to the offset's square (the
      // found point is the reference's foot moved along the surface,
      // which lengthens d^2 by the offset's square), plus 50 % for the
      // surface's curvature and 1e-12 mm^2 for rounding (coordinates of
      // tens of millimetres).
      EXPECT_NEAR((x_found - points[i]).squaredNorm(),
                  (x_reference - points[i]).squaredNorm(),
                  1.5 * offset * offset + 1e-12)
          << i;
      EXPECT_EQ(found_threaded[i].u, found[i].u) << i;
      EXPECT_EQ(found_threaded[i].v, found[i].v) << i;
    }
    EXPECT_LT(worst_mm, 3.0 * CorrespondenceOptions().step_tolerance_mm);
  }
}

// The closest material point the slow way, as the search once found it:
// the nearest of a dense (u, v) grid, then undamped Gauss-Newton with
// ceres::Jet derivatives until its steps stop shrinking the distance.
MaterialPoint ReferenceClosest(const Model& model, const Eigen::Vector3d& p) {
  using Jet2 = ceres::Jet<double, 2>;
  const double u_min = model.config.u_min, u_max = model.config.u_max;
  MaterialPoint best{u_min, 0.0};
  double best_cost = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 60; ++i) {
    for (int j = 0; j < 120; ++j) {
      const MaterialPoint m{u_min + (u_max - u_min) * i / 60,
                            -M_PI + 2 * M_PI * j / 120};
      const double cost = (model.WorldPoint(m.u, m.v) - p).squaredNorm();
      if (cost < best_cost) best = m, best_cost = cost;
    }
  }
  for (int step = 0; step < 100; ++step) {
    const Eigen::Matrix<Jet2, 3, 1> x =
        WorldPointAt(model, Jet2(best.u, 0), Jet2(best.v, 1));
    Eigen::Matrix<double, 3, 2> jacobian;
    Eigen::Vector3d residual;
    for (int k = 0; k < 3; ++k) {
      residual[k] = x[k].a - p[k];
      jacobian.row(k) = x[k].v.transpose();
    }
    const Eigen::Vector2d delta =
        -(jacobian.transpose() * jacobian + 1e-12 * Eigen::Matrix2d::Identity())
             .ldlt()
             .solve(jacobian.transpose() * residual);
    const MaterialPoint trial{std::clamp(best.u + delta[0], u_min, u_max),
                              std::remainder(best.v + delta[1], 2 * M_PI)};
    const double cost = (model.WorldPoint(trial.u, trial.v) - p).squaredNorm();
    if (!(cost < best_cost)) break;
    best = trial;
    best_cost = cost;
  }
  return best;
}

// The truth model with a local field of up to 2 mm per coordinate at its
// 13 x 24 nodes, as the contours' local rounds search it.
Model WithLocalField(Model model) {
  std::mt19937 random(4);
  const LocalGrid grid{13, 24, model.config.u_min, model.config.u_max};
  model.state.local = LocalField::Zero(grid);
  std::uniform_real_distribution<double> offset(-2.0, 2.0);
  for (double& value : model.state.local.values) value = offset(random);
  return model;
}

// The truth model as a solid: a 9 mm wall whose thickness and twist
// difference vary along u, and a local field with a transmural slope.
Model AsSolid(Model model) {
  model.state.globals[kH] = 9.0;
  model.state.globals[kDtau] = 0.1;
  model.state.globals[kWallShift] = 0.4;
  for (size_t k = 0; k < model.state.knots.size(); ++k) {
    model.state.knots[k][kH] = 8.0 + 0.3 * k;
    model.state.knots[k][kDtau] = 0.1 - 0.02 * k;
    model.state.knots[k][kWallShift] = 0.4;
  }
  model = WithLocalField(model);
  model.state.local.slope.assign(model.state.local.values.size(), 0.0);
  for (size_t i = 0; i < model.state.local.slope.size(); ++i) {
    model.state.local.slope[i] = 0.5 * std::sin(0.7 * i);
  }
  return model;
}

// Random points within 3 mm of the bent, twisted truth model (with and
// without a local field; as a solid, searched on its walls w = -+1 and a
// layer between) and of the initialized frame-0 model, many of them
// near the apex pole and across the seam v = +-pi.  Against the search with
// ceres::Jet derivatives (the same steps, as the search was before
// closed-form derivatives): the same distances to 1e-9 mm and material
// points to 1e-6 mm on the model.  Against a slow reference (dense grid,
// then Gauss-Newton to the end): never farther from the data than 1e-6 mm
// more, on the global models; the random field's bumps have local minima
// of their own (0.45 mm farther than the reference's), which neither
// search escapes.
TEST(CorrespondenceTest, MatchesJetDerivativesAndAReferenceOnRandomPoints) {
  Phantom phantom;
  const std::vector<Eigen::Vector3d> data = PhantomPositions(1000, 0, &phantom);
  const Model start = InitializeModel(phantom.truth[0].config, data, {});
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Model local = WithLocalField(phantom.truth[3]);
  const Model solid = AsSolid(phantom.truth[3]);
  for (const Model* model_in : std::initializer_list<const Model*>{
           &phantom.truth[3], &start, &local, &solid}) {
    const Model& model = *model_in;
    const double u_min = model.config.u_min, u_max = model.config.u_max;
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 300; ++i) {
      double u = u_min + (u_max - u_min) * unit(random);
      double v = -M_PI + 2 * M_PI * unit(random);
      if (i % 3 == 1) u = u_min + 0.15 * unit(random);      // Near the apex.
      if (i % 3 == 2) v = M_PI - 0.1 + 0.2 * unit(random);  // Across the seam.
      const double offset = -3.0 + 6.0 * unit(random);
      points.push_back(model.WorldPoint(u, v) +
                       offset * SurfaceNormal(model, u, v));
    }
    std::int64_t evaluations = 0, jet_evaluations = 0;
    CorrespondenceOptions options;
    options.evaluations = &evaluations;
    if (model_in == &solid) {
      for (size_t i = 0; i < points.size(); ++i) {
        options.surfaces.push_back(i % 3 == 0 ? -1.0 : i % 3 == 1 ? 1.0 : 0.4);
      }
    }
    const std::vector<MaterialPoint> found =
        ClosestMaterialPoints(model, points, options);
    options.jet_derivatives = true;
    options.evaluations = &jet_evaluations;
    const std::vector<MaterialPoint> jet =
        ClosestMaterialPoints(model, points, options);
    double worst_mm = 0.0, worst_distance_mm = 0.0, worst_excess_mm = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d x =
          model.WorldPoint(found[i].u, found[i].v, found[i].w);
      const Eigen::Vector3d y = model.WorldPoint(jet[i].u, jet[i].v, jet[i].w);
      worst_mm = std::max(worst_mm, (x - y).norm());
      worst_distance_mm =
          std::max(worst_distance_mm,
                   std::abs((x - points[i]).norm() - (y - points[i]).norm()));
      const MaterialPoint reference = ReferenceClosest(model, points[i]);
      worst_excess_mm = std::max(
          worst_excess_mm,
          (x - points[i]).norm() -
              (model.WorldPoint(reference.u, reference.v) - points[i]).norm());
    }
    // The same steps, so about as many evaluations.
    EXPECT_NEAR(evaluations, jet_evaluations, 0.05 * jet_evaluations);
    EXPECT_LT(worst_mm, 1e-6);
    EXPECT_LT(worst_distance_mm, 1e-9);
    if (model_in != &local && model_in != &solid) {
      EXPECT_LT(worst_excess_mm, 1e-6);
    }
  }
}

}  // namespace
}  // namespace pfdm
