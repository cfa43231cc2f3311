#include "pfdm/fit/stages/initialization.h"

#include <cmath>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {
namespace {

std::vector<Eigen::Vector3d> FirstFrame(const Phantom& phantom) {
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : phantom.points.frames[0].points) {
    points.push_back(p.position);
  }
  return points;
}

TEST(InitializationTest, AxisPointsFromApexToBase) {
  const Phantom phantom = MakePhantom(PhantomOptions());
  const Model model =
      InitializeModel(ModelConfig::Paper(17), FirstFrame(phantom), {});
  const Eigen::Vector3d truth_axis = phantom.truth[0].Rotation().col(2);
  EXPECT_GT(model.Rotation().col(2).dot(truth_axis),
            std::cos(3.0 * M_PI / 180));
  // The model spans the data: apex to base is about 110 mm.
  const double length = model.state.globals[kA0] * 0.8 * 1.5;
  EXPECT_NEAR(length, 110.0, 3.0);
  EXPECT_NEAR(model.Rotation().determinant(), 1.0, 1e-12);
}

TEST(InitializationTest, HintSetsTheAxis) {
  const Phantom phantom = MakePhantom(PhantomOptions());
  const Model& truth = phantom.truth[0];
  const AxisHint hint{truth.WorldPoint(-M_PI / 2, 0.0),
                      truth.WorldPoint(truth.config.u_max, 0.0) * 0.5 +
                          truth.WorldPoint(truth.config.u_max, M_PI) * 0.5};
  const Model model =
      InitializeModel(ModelConfig::Paper(17), FirstFrame(phantom), hint);
  EXPECT_TRUE(model.Rotation().col(2).isApprox(truth.Rotation().col(2), 1e-9));
}

TEST(InitializationTest, MovesWithRigidlyMovedData) {
  const Phantom phantom = MakePhantom(PhantomOptions());
  const std::vector<Eigen::Vector3d> points = FirstFrame(phantom);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, -1).normalized())
          .toRotationMatrix();
  const Eigen::Vector3d shift(-40.0, 15.0, 220.0);
  std::vector<Eigen::Vector3d> moved;
  for (const auto& p : points) moved.push_back(rotation * p + shift);
  const Model a = InitializeModel(ModelConfig::Paper(17), points, {});
  const Model b = InitializeModel(ModelConfig::Paper(17), moved, {});
  EXPECT_TRUE((rotation * a.Rotation()).isApprox(b.Rotation(), 1e-9));
  EXPECT_NEAR(a.state.globals[kA0], b.state.globals[kA0], 1e-9);
  EXPECT_NEAR(a.state.globals[kA1], b.state.globals[kA1], 1e-9);
}

// InitializeModel without a hint is InitializeModelAlong the principal
// axis, to the last bit, and either sign of a line gives the same model.
TEST(InitializationTest, AlongThePrincipalAxisIsTheDefault) {
  const Phantom phantom = MakePhantom(PhantomOptions());
  const std::vector<Eigen::Vector3d> points = FirstFrame(phantom);
  const Model a = InitializeModel(ModelConfig::Paper(17), points, {});
  const Eigen::Vector3d axis = PrincipalAxes(points).col(2);
  const Model b = InitializeModelAlong(ModelConfig::Paper(17), points, axis);
  const Model c = InitializeModelAlong(ModelConfig::Paper(17), points, -axis);
  EXPECT_EQ(a.state.center, b.state.center);
  EXPECT_EQ(a.state.quaternion, b.state.quaternion);
  EXPECT_EQ(a.state.globals, b.state.globals);
  EXPECT_TRUE(c.Rotation().col(2).isApprox(a.Rotation().col(2), 1e-12));
  EXPECT_NEAR(c.state.globals[kA0], a.state.globals[kA0], 1e-9);
}

// A mid-ventricular segment (no apex, ED heights 30-72 %): the cup starts
// closing where the points' radius profile closes, near the phantom's apex
// 28.5 mm below them, not at their lowest ring.
TEST(InitializationTest, ASegmentWithoutItsApexStartsWithTheApexBelowIt) {
  LvPhantomOptions options;
  options.region = LvRegion::kMidventricular;
  options.num_frames = 1;
  const LvPhantom phantom = MakeLvPhantom(options);
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : phantom.points.frames[0].points) {
    points.push_back(p.position);
  }
  const Eigen::Isometry3d& pose = phantom.truth[0].world_from_body;
  const Model model = InitializeModelAlong(ModelConfig::Paper(17), points,
                                           pose.linear().col(2));
  const Eigen::Vector3d apex =
      pose.inverse() * model.WorldPoint(model.config.u_min, 0.0);
  EXPECT_NEAR(apex.z(), 0.0, 3.0);
  EXPECT_LT(apex.head<2>().norm(), 1.0);
  // Full data keep their lowest point as the apex.
  const Phantom full = MakePhantom(PhantomOptions());
  const Model model_full =
      InitializeModel(ModelConfig::Paper(17), FirstFrame(full), {});
  double lowest = 1e9;
  for (const Eigen::Vector3d& p : FirstFrame(full)) {
    lowest = std::min(lowest, p.dot(model_full.Rotation().col(2)));
  }
  EXPECT_NEAR(model_full.WorldPoint(model_full.config.u_min, 0.0)
                  .dot(model_full.Rotation().col(2)),
              lowest, 1e-9);
}

}  // namespace
}  // namespace pfdm
