#include "pfdm/fit/correspondence.h"

#include <cmath>

#include "gtest/gtest.h"
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

}  // namespace
}  // namespace pfdm
