#include "pfdm/io/segmentation_overlay.h"

#include <algorithm>

#include "gtest/gtest.h"
#include "pfdm/testing/mask_phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// The default model's epicardium cut by a slice half-way up: every cut
// point lies in the slice's plane and on the surface, within 0.3 % of the
// model's size of a dense sample of it, and the meridians all reach it.
TEST(SegmentationOverlayTest, CutLiesOnTheSurface) {
  const ModelConfig config = ModelConfig::Paper(5);
  const Model model = Model::Uniform(config, DefaultFunctionValues());
  std::vector<Eigen::Vector3d> surface;
  for (int n = 0; n <= 1000; ++n) {
    const double u = config.u_min + (config.u_max - config.u_min) * n / 1000;
    for (int m = 0; m < 360; ++m) {
      surface.push_back(model.WorldPoint(u, -kPi + kPi * m / 180, 1.0));
    }
  }
  Eigen::Vector3d low = surface[0], high = surface[0];
  for (const Eigen::Vector3d& x : surface) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  const double size = (high - low).norm(), step = size / 60;
  LabelVolume volume;
  volume.nx = volume.ny = 64;
  volume.nz = 11;
  volume.nt = 1;
  volume.labels.assign(64 * 64 * 11, 0);
  volume.world_from_voxel.diagonal() << step, step, (high.z() - low.z()) / 10,
      1.0;
  volume.world_from_voxel.topRightCorner<3, 1>()
      << 0.5 * (low + high).x() - 32 * step,
      0.5 * (low + high).y() - 32 * step, low.z();
  const std::vector<Eigen::Vector2d> cut = WallCut(model, 1.0, volume, 5, 90);
  ASSERT_EQ(cut.size(), 90u);
  for (const Eigen::Vector2d& p : cut) {
    const Eigen::Vector3d x = volume.World(p.x(), p.y(), 5);
    EXPECT_NEAR(x.z(), volume.World(0, 0, 5).z(), 1e-9 * size);
    double nearest = 1e300;
    for (const Eigen::Vector3d& s : surface) {
      nearest = std::min(nearest, (s - x).norm());
    }
    EXPECT_LT(nearest, 0.003 * size);
  }
}

// The SVG shows frames 0 and ES by three slices.
TEST(SegmentationOverlayTest, PanelsOfTheMask) {
  const MaskPhantom mask = MakeMaskPhantom(MaskPhantomOptions());
  const MaskContours contours =
      ExtractMaskContours(mask.volume, MaskPhantomOptions().labels);
  const Model model =
      Model::Uniform(ModelConfig::Paper(5), DefaultFunctionValues());
  const std::string svg =
      SegmentationOverlaySvg(mask.volume, MaskPhantomOptions().labels, contours,
                             {model, model, model}, 2);
  EXPECT_EQ(CountOf(svg, "<text"), 6);
  EXPECT_EQ(CountOf(svg, "frame 2, slice"), 3);
  EXPECT_GT(CountOf(svg, "fill=\"#a33\""), 1000);
}

}  // namespace
}  // namespace pfdm
