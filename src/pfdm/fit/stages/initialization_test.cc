#include "pfdm/fit/stages/initialization.h"

#include <cmath>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
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

}  // namespace
}  // namespace pfdm
