#include "pfdm/fit/residuals/point_residual.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

struct State {
  double center[3] = {4.0, -7.0, 12.0};
  double quaternion[4];
  FunctionValues globals;
  FunctionValues knot0;
  FunctionValues knot1;
};

// A bent, twisted, offset state with knots that differ.
State GeneralState() {
  State s;
  s.quaternion[0] = 1.0;
  s.quaternion[1] = s.quaternion[2] = s.quaternion[3] = 0.0;
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  f[kB0] = 1.5;
  f[kB1] = 0.4;
  f[kTau] = 0.2;
  f[kE1o] = 1.0;
  f[kE2o] = -2.0;
  f[kE3o] = 0.5;
  s.globals = s.knot0 = s.knot1 = f;
  s.knot1[kA1] = 0.7;
  return s;
}

void IdentityPose(State* s) {
  s->quaternion[0] = 1.0;
  s->quaternion[1] = s->quaternion[2] = s->quaternion[3] = 0.0;
  s->center[0] = s->center[1] = s->center[2] = 0.0;
}

TEST(PointResidualTest, ResidualIsModelPointMinusData) {
  State s = GeneralState();
  IdentityPose(&s);
  const Eigen::Vector3d data(1.0, 2.0, 3.0);
  const FunctionMask none = 0;  // Every function from the globals.
  std::unique_ptr<ceres::CostFunction> cost(
      PointResidual::Create(data, 0.0, 0.0, 0.5, none, false));
  const double* parameters[] = {s.center, s.quaternion, s.globals.data(),
                                s.knot0.data(), s.knot1.data()};
  double residual[3];
  ASSERT_TRUE(cost->Evaluate(parameters, residual, nullptr));
  // u = v = 0: e = (a0 a1, 0, 0) on a ring of half extent a1; the bend
  // lifts it by b0 (cos(pi/2 (a1 - b1)) - J0(pi/2 a1) cos(pi/2 b1)); twist
  // and offsets follow.
  const FunctionValues& f = s.globals;
  const double e1 = f[kA0] * f[kA1];
  const double z = f[kB0] * (std::cos(M_PI / 2 * (e1 / f[kA0] - f[kB1])) -
                             std::cyl_bessel_j(0.0, M_PI / 2 * f[kA1]) *
                                 std::cos(M_PI / 2 * f[kB1]));
  const Eigen::Vector3d expected(e1 * std::cos(f[kTau]) + f[kE1o],
                                 e1 * std::sin(f[kTau]) + f[kE2o], z + f[kE3o]);
  EXPECT_NEAR(residual[0], expected.x() - data.x(), 1e-12);
  EXPECT_NEAR(residual[1], expected.y() - data.y(), 1e-12);
  EXPECT_NEAR(residual[2], expected.z() - data.z(), 1e-12);
}

TEST(PointResidualTest, KnotsAreBlendedByTheHatWeights) {
  State s = GeneralState();
  IdentityPose(&s);
  const FunctionMask free_a1 = 1u << kA1;
  std::unique_ptr<ceres::CostFunction> cost(PointResidual::Create(
      Eigen::Vector3d::Zero(), 0.0, 0.0, 0.25, free_a1, true));
  s.globals = DefaultFunctionValues();
  s.globals[kA0] = 10.0;
  s.globals[kB0] = 0.0;
  s.knot0[kA1] = 0.2;
  s.knot1[kA1] = 0.6;
  const double* parameters[] = {s.center, s.quaternion, s.globals.data(),
                                s.knot0.data(), s.knot1.data()};
  double residual[3];
  ASSERT_TRUE(cost->Evaluate(parameters, residual, nullptr));
  EXPECT_NEAR(residual[0], 10.0 * (0.75 * 0.2 + 0.25 * 0.6), 1e-12);
}

}  // namespace
}  // namespace pfdm
