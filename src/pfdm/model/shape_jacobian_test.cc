#include "pfdm/model/shape_jacobian.h"

#include "gtest/gtest.h"
#include "pfdm/model/model.h"
#include "pfdm/model/model_point.h"

namespace pfdm {
namespace {

TEST(ShapeJacobianTest, ShapeMatchesReferenceShape) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 70.0;
  f[kA1] = 0.3;
  f[kEps1] = 0.7;
  f[kB0] = 2.0;
  f[kB1] = 0.2;
  f[kTau] = 0.4;
  f[kE2o] = -1.0;
  for (double u : {-1.5707963267948966, -0.5, 0.4}) {
    for (double v : {-3.0, 0.0, 1.2}) {
      const Angles<double> angles = MakeAngles(u, v);
      ShapeJacobian jacobian;
      EXPECT_TRUE(
          ShapeAndJacobian(f.data(), angles, false, &jacobian)
              .isApprox(ReferenceShape(f.data(), angles, false), 1e-14));
      EXPECT_TRUE(
          ShapeAndJacobian(f.data(), angles, false, nullptr)
              .isApprox(ReferenceShape(f.data(), angles, false), 1e-14));
    }
  }
}

// Offsets enter with the identity; tau turns the point about z.
TEST(ShapeJacobianTest, OffsetAndTwistColumns) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 10.0;
  ShapeJacobian jacobian;
  const Eigen::Vector3d s =
      ShapeAndJacobian(f.data(), MakeAngles(0.0, 0.0), true, &jacobian);
  EXPECT_EQ(jacobian.col(kE1o), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(jacobian.col(kE3o), Eigen::Vector3d(0, 0, 1));
  EXPECT_TRUE(jacobian.col(kTau).isApprox(Eigen::Vector3d(-s.y(), s.x(), 0)));
}

}  // namespace
}  // namespace pfdm
