#include "pfdm/phantom/lv_slices.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "gtest/gtest.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

// The cut lies on the plane and on the moved surface: at ED (no motion) on
// surface w at the plane's height, at end-systole on the plane still.
TEST(LvSlicesTest, CutsTheMovedWallWhereThePlaneIs) {
  const LvShape shape;
  const LvDeformation design;
  const Eigen::Isometry3d pose = LvWorldPose();
  const LvImagePlane plane = ShortAxisPlane(pose, 40.0);
  EXPECT_NEAR(plane.normal.norm(), 1.0, 1e-12);
  const LvFrameMotion ed = ScenarioMotion(LvKinematics::kSystole, 0, 5, true);
  const LvFrameMotion es = ScenarioMotion(LvKinematics::kSystole, 4, 5, true);
  for (double w : {-1.0, 0.0, 1.0}) {
    const auto at_ed = SliceCut(shape, design, ed, plane, 0.7, w);
    ASSERT_TRUE(at_ed.has_value());
    const Eigen::Vector3d body = pose.inverse() * *at_ed;
    EXPECT_NEAR(body.z(), 40.0, 1e-9);
    EXPECT_NEAR(shape.Transmural(body), w, 1e-9);
    EXPECT_NEAR(std::atan2(body.y(), body.x()), 0.7, 1e-9);
    const auto at_es = SliceCut(shape, design, es, plane, 0.7, w);
    ASSERT_TRUE(at_es.has_value());
    EXPECT_NEAR(plane.normal.dot(*at_es) - plane.offset, 0.0, 1e-9);
    // Another material point: the base descended through the plane.
    EXPECT_GT((*at_es - *at_ed).norm(), 1.0);
  }
  // Above the base plane, and above where the base has descended to.
  EXPECT_FALSE(SliceCut(shape, design, ed, ShortAxisPlane(pose, 96.0), 0.0, 0)
                   .has_value());
  EXPECT_FALSE(SliceCut(shape, design, es, ShortAxisPlane(pose, 90.0), 0.0, 0)
                   .has_value());
}

// A long-axis plane through the ED axis: at ED it cuts ring nu at the
// plane's longitude (or the opposite one), on surface w; at end-systole,
// twisted, at another longitude but on the plane still.
TEST(LvSlicesTest, LongAxisPlaneCutsEachRingOnItsTwoSides) {
  const LvShape shape;
  const LvDeformation design;
  const Eigen::Isometry3d pose = LvWorldPose();
  const double angle = 0.9;
  const LvImagePlane plane = LongAxisPlane(pose, angle);
  EXPECT_NEAR(plane.normal.norm(), 1.0, 1e-12);
  const LvFrameMotion ed = ScenarioMotion(LvKinematics::kSystole, 0, 5, true);
  const LvFrameMotion es = ScenarioMotion(LvKinematics::kSystole, 4, 5, true);
  for (double side : {0.0, 3.14159265358979}) {
    const auto at_ed =
        LongAxisCut(shape, design, ed, plane, 1.2, angle + side, -1.0);
    ASSERT_TRUE(at_ed.has_value());
    const Eigen::Vector3d body = pose.inverse() * *at_ed;
    EXPECT_NEAR(shape.Transmural(body), -1.0, 1e-9);
    EXPECT_NEAR(std::remainder(std::atan2(body.y(), body.x()) - angle - side,
                               2 * 3.14159265358979),
                0.0, 1e-9);
    const auto at_es =
        LongAxisCut(shape, design, es, plane, 1.2, angle + side, -1.0);
    ASSERT_TRUE(at_es.has_value());
    EXPECT_NEAR(plane.normal.dot(*at_es) - plane.offset, 0.0, 1e-9);
    EXPECT_GT((*at_es - *at_ed).norm(), 1.0);
  }
  // A quarter turn away the ring does not cross the plane within the
  // bracket.
  EXPECT_FALSE(LongAxisCut(shape, design, ed, plane, 1.2, angle + 1.57, 0.0)
                   .has_value());
}

// The phantom's short-axis slices: untracked contours (an id per point and
// frame) on fixed planes, in-plane noise only; the endocardium and the
// epicardium named with wall tags.
TEST(LvSlicesTest, PhantomSlicesAreContoursOnFixedPlanes) {
  LvPhantomOptions options;
  options.sampling = LvSampling::kSaxSlices;
  options.region = LvRegion::kMidventricular;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 600;
  const LvPhantom phantom = MakeLvPhantom(options);
  EXPECT_TRUE(phantom.tag_material.empty());
  const LvShape shape;
  std::vector<LvImagePlane> planes;
  for (double h : LvSliceHeights(options)) {
    planes.push_back(
        ShortAxisPlane(phantom.truth[0].world_from_body, h * shape.base_z()));
  }
  std::set<std::int64_t> ids;
  for (const Frame& frame : phantom.points.frames) {
    // 3 planes x 2 surfaces x 100; the segment stays within the planes.
    EXPECT_EQ(frame.points.size(), 600u);
    int endo = 0;
    for (const DataPoint& p : frame.points) {
      EXPECT_TRUE(ids.insert(p.id).second) << p.id;
      double nearest = 1e9;
      for (const LvImagePlane& plane : planes) {
        nearest = std::min(
            nearest, std::abs(plane.normal.dot(p.position) - plane.offset));
      }
      EXPECT_LT(nearest, 1e-9);
      endo += p.layer == WallLayer::kEndocardium;
      EXPECT_NE(p.layer, WallLayer::kAnywhere);
    }
    EXPECT_EQ(endo, 300);
  }
  // Noise of 0.5 mm per coordinate in the plane: ED points lie 0.5 mm RMS
  // off their surface's radius at their height.
  double sum = 0.0;
  int n = 0;
  for (const DataPoint& p : phantom.points.frames[0].points) {
    const Eigen::Vector3d body =
        phantom.truth[0].world_from_body.inverse() * p.position;
    const double w = p.layer == WallLayer::kEndocardium ? -1.0 : 1.0;
    const double radius =
        shape.Position(shape.NuAtHeight(body.z(), w), 0.0, w).x();
    sum += std::pow(body.head<2>().norm() - radius, 2);
    ++n;
  }
  EXPECT_NEAR(std::sqrt(sum / n), 0.5, 0.05);
}

}  // namespace
}  // namespace pfdm
