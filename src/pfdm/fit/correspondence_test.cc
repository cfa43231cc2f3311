#include "pfdm/fit/correspondence.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/fit/initialization.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {
namespace {

Model TruthModel() {
  PhantomOptions options;
  options.num_points = 1;
  options.num_frames = 5;
  return MakePhantom(options).truth[3];  // Twisted, offset, contracted.
}

TEST(CorrespondenceTest, FindsTheMaterialPointOfPointsOffTheSurface) {
  const Model model = TruthModel();
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
  const Model model = TruthModel();
  for (double v : {-2.5, -0.4, 1.2, 2.9}) {
    const double u = -M_PI / 2 + 0.02;
    const Eigen::Vector3d point = model.WorldPoint(u, v);
    const MaterialPoint found = ClosestMaterialPoints(model, {point})[0];
    EXPECT_LT((model.WorldPoint(found.u, found.v) - point).norm(), 1e-6) << v;
  }
}

TEST(CorrespondenceTest, NormalIsUnitAndOrthogonalToTheSurface) {
  const Model model = TruthModel();
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

// The search stops once a step moves the model point by less than
// step_tolerance_mm; running every step instead (tolerance 0, the search as
// it was before the early stop) must find the same material points, on the
// truth and on a frame-0 start far from the data, and threads must not
// change a bit of the result.
TEST(CorrespondenceTest, EarlyStopAndThreadsFindTheSameMaterialPoints) {
  PhantomOptions phantom_options;
  phantom_options.num_points = 3000;
  phantom_options.num_frames = 5;
  const Phantom phantom = MakePhantom(phantom_options);
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : phantom.points.frames[3].points) {
    points.push_back(p.position);
  }
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
      // 1e-6 mm on the model: a thousandth of the data's noise
      // (0.5 mm) to the power of three.
      worst_mm =
          std::max(worst_mm, (model.WorldPoint(found[i].u, found[i].v) -
                              model.WorldPoint(reference[i].u, reference[i].v))
                                 .norm());
      // Distances to the data agree to 1e-9 mm.
      EXPECT_NEAR(
          (model.WorldPoint(found[i].u, found[i].v) - points[i]).norm(),
          (model.WorldPoint(reference[i].u, reference[i].v) - points[i]).norm(),
          1e-9)
          << i;
      EXPECT_EQ(found_threaded[i].u, found[i].u) << i;
      EXPECT_EQ(found_threaded[i].v, found[i].v) << i;
    }
    EXPECT_LT(worst_mm, 1e-6);
  }
}

}  // namespace
}  // namespace pfdm
