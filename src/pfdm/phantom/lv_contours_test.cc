#include "pfdm/phantom/lv_contours.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// sax-slices with 3 long-axis planes: the long-axis contours lie on their
// planes (no noise), run from near the apex to the base, and their ids
// follow the short-axis contours' in each frame.
TEST(LvContoursTest, LongAxisContoursLieOnTheirPlanes) {
  LvPhantomOptions options;
  options.sampling = LvSampling::kSaxSlices;
  options.num_long_axis_planes = 3;
  options.num_tags = 1200;
  options.noise_mm = 0.0;
  const LvPhantom phantom = MakeLvPhantom(options);
  const LvShape shape;
  const Eigen::Isometry3d ed_pose = phantom.truth[0].world_from_body;
  std::vector<LvImagePlane> planes;
  for (int k = 0; k < 3; ++k) {
    planes.push_back(LongAxisPlane(ed_pose, 3.14159265358979 * k / 3));
  }
  for (const Frame& frame : phantom.points.frames) {
    int on_long_axis = 0;
    double low = 1e9, high = -1e9;
    for (const DataPoint& p : frame.points) {
      bool on_plane = false;
      for (const LvImagePlane& plane : planes) {
        on_plane |=
            std::abs(plane.normal.dot(p.position) - plane.offset) < 1e-6;
      }
      if (!on_plane) continue;
      ++on_long_axis;
      const double z = (ed_pose.inverse() * p.position).z();
      low = std::min(low, z);
      high = std::max(high, z);
    }
    // 9 short-axis and 3 long-axis contours share 1,200 points: 100 each.
    EXPECT_GE(on_long_axis, 290) << frame.index;
    EXPECT_LT(low, 0.2 * shape.base_z()) << frame.index;
    EXPECT_GT(high, 0.8 * shape.base_z()) << frame.index;
    for (size_t i = 1; i < frame.points.size(); ++i) {
      EXPECT_EQ(frame.points[i].id, frame.points[i - 1].id + 1);
    }
  }
}

// --wall_tags endo (epi): every contour point at ED lies on the
// endocardium, w = -1 (the epicardium, w = 1), and is labelled so, as
// biv-me's lv-cavity (lv-epi) contours are; tags too lie on it.
TEST(LvContoursTest, OneWallsContoursLieOnThatWall) {
  const struct {
    LvTagLayer tags;
    WallLayer layer;
    double w;
  } walls[] = {{LvTagLayer::kEndocardium, WallLayer::kEndocardium, -1.0},
               {LvTagLayer::kEpicardium, WallLayer::kEpicardium, 1.0}};
  for (const auto& wall : walls) {
    LvPhantomOptions options;
    options.sampling = LvSampling::kSaxSlices;
    options.tags = wall.tags;
    options.num_tags = 900;
    options.noise_mm = 0.0;
    const LvPhantom contours = MakeLvPhantom(options);
    const LvShape shape(contours.options.shape);
    const Frame& ed = contours.points.frames[0];
    ASSERT_EQ(ed.points.size(), 900u);  // 9 slices of 100, one wall each.
    const Eigen::Isometry3d body_from_world =
        contours.truth[0].world_from_body.inverse();
    for (const DataPoint& p : ed.points) {
      EXPECT_EQ(p.layer, wall.layer);
      EXPECT_NEAR(shape.Transmural(body_from_world * p.position), wall.w, 1e-6);
    }
    options.sampling = LvSampling::kTags;
    const LvPhantom tags = MakeLvPhantom(options);
    for (const Eigen::Vector3d& body : tags.tag_material) {
      EXPECT_NEAR(shape.Transmural(body), wall.w, 1e-9);
    }
  }
}

}  // namespace
}  // namespace pfdm
