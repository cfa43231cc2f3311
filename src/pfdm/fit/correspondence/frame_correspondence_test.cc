#include "pfdm/fit/correspondence/frame_correspondence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A solid spheroid with a 10 mm wall (h in mm).
Model SolidSpheroid() {
  Model model = TestSpheroid(9);
  model.config.MakeSolid();
  model.state.globals[kH] = 10.0;
  for (FunctionValues& knot : model.state.knots) knot[kH] = 10.0;
  return model;
}

// Inside the paper model's u range [-pi/2, pi/6].
const MaterialPoint kAt[] = {
    {0.3, 1.0, 0.0}, {-0.4, -2.0, 0.0}, {0.1, 2.5, 0.0}, {-0.8, 0.4, 0.0}};

// The search stops once a step would move the model point by under 1e-4
// mm (CorrespondenceOptions::step_tolerance_mm): about 4e-6 of an angle at
// the spheroid's 25 mm radius.
constexpr double kFoundMm = 1e-4, kFoundAngle = 1e-5;

TEST(FrameCorrespondenceTest, ListsAndMeasures) {
  const std::vector<MaterialPoint> material(std::begin(kAt), std::end(kAt));
  const std::vector<MaterialPoint> listed = Listed(material, {3, 1});
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].u, -0.8);
  EXPECT_EQ(listed[1].v, -2.0);
  EXPECT_EQ(MaxDistance({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)},
                        {Eigen::Vector3d(3, 4, 0), Eigen::Vector3d(1, 1, 1)}),
            5.0);
}

// Points on the mid-wall are found where they are, only the listed ones;
// the listed points below the rim pull along the normal there.
TEST(FrameCorrespondenceTest, FindsTheListedPointsOnTheMidwall) {
  const Model model = TestSpheroid(9);
  std::vector<Eigen::Vector3d> points;
  for (const MaterialPoint& m : kAt)
    points.push_back(model.WorldPoint(m.u, m.v));
  std::vector<MaterialPoint> material(4);
  std::vector<Eigen::Vector3d> normals(4, Eigen::Vector3d::Zero()), found;
  UpdateClosest(model, points, {0, 2}, 1, std::vector<double>(4, 0.0),
                std::vector<bool>(4, false), false, &material, &normals,
                &found);
  for (size_t i : {0, 2}) {
    EXPECT_NEAR(material[i].u, kAt[i].u, kFoundAngle) << i;
    EXPECT_NEAR(material[i].v, kAt[i].v, kFoundAngle) << i;
    EXPECT_NEAR((normals[i] - SurfaceNormal(model, kAt[i].u, kAt[i].v)).norm(),
                0.0, kFoundAngle)
        << i;
  }
  EXPECT_NEAR((found[1] - points[2]).norm(), 0.0, kFoundMm);
  EXPECT_EQ(material[1].u, 0.0);
  EXPECT_EQ(normals[3], Eigen::Vector3d::Zero());
}

// With no point to search (a frame of tracked tags alone) nothing changes,
// the grid included: it follows the model only for a search.
TEST(FrameCorrespondenceTest, NoPointsLeaveTheGridWhereItWas) {
  const Model model = TestSpheroid(9);
  Model moved = model;
  moved.state.center[0] += 20.0;
  const std::vector<Eigen::Vector3d> points = {moved.WorldPoint(0.3, 1.0)};
  std::vector<MaterialPoint> material(1);
  std::vector<Eigen::Vector3d> normals(1, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> found = {Eigen::Vector3d::Ones()};
  SurfaceGrid grid(model);
  ASSERT_EQ(grid.builds(), 1);
  UpdateClosest(moved, points, {}, 1, {0.0}, {false}, false, &material,
                &normals, &found, DepthRanking(), &grid);
  EXPECT_EQ(grid.builds(), 1);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(material[0].u, 0.0);
  UpdateClosest(moved, points, {0}, 1, {0.0}, {false}, false, &material,
                &normals, &found, DepthRanking(), &grid);
  EXPECT_EQ(grid.builds(), 2);  // 20 mm of drift.
  EXPECT_NEAR(material[0].u, 0.3, kFoundAngle);
}

// In a solid, a contour point is sought on its own wall: an epicardial
// point 5 mm outside the mid-wall is on w = +1, at distance 0.
TEST(FrameCorrespondenceTest, FindsContoursOnTheirWall) {
  const Model model = SolidSpheroid();
  std::vector<Eigen::Vector3d> points;
  for (const MaterialPoint& m : kAt) {
    points.push_back(model.WorldPoint(m.u, m.v, 1.0));
  }
  std::vector<MaterialPoint> material(4);
  std::vector<Eigen::Vector3d> normals(4), found;
  UpdateClosest(model, points, {0, 1, 2, 3}, 2, std::vector<double>(4, 1.0),
                std::vector<bool>(4, false), false, &material, &normals,
                &found);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(material[i].w, 1.0) << i;
    EXPECT_NEAR((found[i] - points[i]).norm(), 0.0, kFoundMm) << i;
  }
}

// In a solid, one warm search of points on both walls' contours and on the
// mid-wall (one point left unlisted): each listed point comes out exactly
// as a search of its own surface alone from the same hint finds it, model
// point and normal with it.  (The walls' points skip the mid-wall search,
// whose answer they never used.)
TEST(FrameCorrespondenceTest, EachPointIsSoughtOnItsOwnSurfaceAlone) {
  const Model model = SolidSpheroid();
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  std::vector<double> layer_w;
  for (const MaterialPoint& m : kAt) {
    for (double w : {-1.0, 0.0, 1.0}) {
      const Eigen::Vector3d off(0.4 * w + 0.3, -0.5, 0.2 * m.v);
      points.push_back(model.WorldPoint(m.u, m.v, w) + off);
      material.push_back({m.u + 0.02, m.v - 0.03, w});
      layer_w.push_back(w);
    }
  }
  const std::vector<MaterialPoint> hints = material;
  std::vector<size_t> which(points.size() - 1);
  std::iota(which.begin(), which.end(), 1);
  std::vector<Eigen::Vector3d> normals(points.size()), found;
  UpdateClosest(model, points, which, 1, layer_w,
                std::vector<bool>(points.size(), false), /*warm=*/true,
                &material, &normals, &found);
  const SurfaceGrid grid(model);
  for (size_t j = 0; j < which.size(); ++j) {
    const size_t i = which[j];
    CorrespondenceOptions alone;
    if (layer_w[i] != 0.0) alone.surfaces = {layer_w[i]};
    alone.hints = {hints[i]};
    std::vector<Eigen::Vector3d> point, normal;
    const MaterialPoint expected = ClosestMaterialPointsFrom(
        grid, model, {points[i]}, alone, &point, &normal)[0];
    EXPECT_EQ(material[i].u, expected.u) << i;
    EXPECT_EQ(material[i].v, expected.v) << i;
    EXPECT_EQ(material[i].w, layer_w[i]) << i;
    EXPECT_EQ(found[j], point[0]) << i;
    EXPECT_EQ(normals[i], normal[0]) << i;
  }
  EXPECT_EQ(material[0].u, hints[0].u);  // Not listed: untouched.
}

// Held depths: tags whose depth is assigned keep their material point's w
// (the mid-wall's 0 among them) and come out exactly as a search of that
// layer alone from the same hint finds them; unheld, the same search ranks
// them afresh.
TEST(FrameCorrespondenceTest, HeldDepthsAreSoughtOnTheirOwnLayer) {
  const Model model = SolidSpheroid();
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  int j = 0;
  for (const MaterialPoint& m : kAt) {
    for (double w : {-0.7, 0.0, 0.45}) {
      const Eigen::Vector3d off(0.3, -0.2 * w, 0.1 * (j++ % 3));
      points.push_back(model.WorldPoint(m.u, m.v, w) + off);
      material.push_back({m.u + 0.02, m.v - 0.03, w});
    }
  }
  const std::vector<MaterialPoint> hints = material;
  std::vector<size_t> which(points.size());
  std::iota(which.begin(), which.end(), 0);
  const std::vector<double> layer_w(points.size(), 0.0);
  const std::vector<bool> assign_depth(points.size(), true);
  DepthRanking held;
  held.hold = true;
  std::vector<Eigen::Vector3d> normals(points.size()), found;
  UpdateClosest(model, points, which, 1, layer_w, assign_depth,
                /*warm=*/true, &material, &normals, &found, held);
  const SurfaceGrid grid(model);
  for (size_t i = 0; i < points.size(); ++i) {
    CorrespondenceOptions alone;
    if (hints[i].w != 0.0) alone.surfaces = {hints[i].w};
    alone.hints = {hints[i]};
    std::vector<Eigen::Vector3d> point, normal;
    const MaterialPoint expected = ClosestMaterialPointsFrom(
        grid, model, {points[i]}, alone, &point, &normal)[0];
    EXPECT_EQ(material[i].w, hints[i].w) << i;
    EXPECT_EQ(material[i].u, expected.u) << i;
    EXPECT_EQ(material[i].v, expected.v) << i;
    EXPECT_EQ(found[i], point[0]) << i;
  }
  std::vector<MaterialPoint> ranked = hints;
  UpdateClosest(model, points, which, 1, layer_w, assign_depth,
                /*warm=*/true, &ranked, &normals, &found);
  int changed = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    changed += ranked[i].w != hints[i].w;
  }
  EXPECT_GT(changed, 0);
}

// Tags through the wall, ten bands of latitude of 24 tags each evenly
// spread across it, take their rank's depth in their band; a tag moved
// from the mid-wall to its rank's surface moves by up to the wall's half
// thickness, and ranking again moves none.
TEST(FrameCorrespondenceTest, RanksTagsAcrossTheWall) {
  const Model model = SolidSpheroid();
  const int bands = 10, per_band = kMinBand;
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  std::vector<double> depth;
  std::vector<size_t> which;
  for (int j = 0; j < per_band; ++j) {
    for (int b = 0; b < bands; ++b) {
      const double w = -1.0 + (2.0 * j + 1.0) / per_band;
      const double u = -1.0 + 0.2 * b + 0.005 * j, v = 0.26 * j;
      which.push_back(points.size());
      points.push_back(model.WorldPoint(u, v, w));
      material.push_back({u, v, 0.0});
      depth.push_back(w);
    }
  }
  double moved = -1.0;
  RerankDepths(model, points, which, &material, DepthRanking(), &moved);
  EXPECT_NEAR(moved, 5.0, 0.5);
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(material[i].w, depth[i], 1.0 / per_band) << i;
  }
  RerankDepths(model, points, which, &material, DepthRanking(), &moved);
  EXPECT_EQ(moved, 0.0);
}

// Two tags of each band of 24 lie 4 mm outside either surface (outliers):
// ranked with the others, they push the outermost tags' w 2/24 inward; left
// out (a band of 1 mm), they take -1 and +1 and the others keep the ranks
// they have alone.
TEST(FrameCorrespondenceTest, RanksLeaveOutTagsOutsideTheWall) {
  const Model model = SolidSpheroid();
  const int bands = 10, inliers = kMinBand - 2;
  std::vector<Eigen::Vector3d> points;
  std::vector<MaterialPoint> material;
  std::vector<double> depth;
  for (int j = 0; j < kMinBand; ++j) {
    for (int b = 0; b < bands; ++b) {
      const double w = j < inliers ? -1.0 + (2.0 * j + 1.0) / inliers
                                   : (j == inliers ? -1.8 : 1.8);
      const double u = -1.0 + 0.2 * b + 0.005 * j, v = 0.26 * j;
      points.push_back(model.WorldPoint(u, v, w));
      material.push_back({u, v, 0.0});
      depth.push_back(w);
    }
  }
  std::vector<size_t> which(points.size());
  for (size_t i = 0; i < which.size(); ++i) which[i] = i;
  std::vector<MaterialPoint> ranked = material;
  RerankDepths(model, points, which, &ranked);
  double outermost = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::abs(depth[i]) < 1.0) {
      outermost = std::max(outermost, std::abs(ranked[i].w));
    }
  }
  EXPECT_NEAR(outermost, 1.0 - 3.0 / kMinBand, 1e-9);
  RerankDepths(model, points, which, &material, DepthRanking{1.0});
  for (size_t i = 0; i < points.size(); ++i) {
    const double expected = std::abs(depth[i]) < 1.0 ? depth[i]
                            : depth[i] < 0.0         ? -1.0
                                                     : 1.0;
    EXPECT_NEAR(material[i].w, expected, 1e-9) << i;
  }
}

}  // namespace
}  // namespace pfdm
