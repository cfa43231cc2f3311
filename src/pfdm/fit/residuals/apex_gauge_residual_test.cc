#include "pfdm/fit/residuals/apex_gauge_residual.h"

#include <array>
#include <memory>
#include <vector>

#include "Eigen/Geometry"
#include "ceres/gradient_checker.h"
#include "ceres/manifold.h"
#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

struct Pose {
  std::array<double, 3> center;
  std::array<double, 4> quaternion;  // w, x, y, z.
  FunctionValues globals = DefaultFunctionValues();
};

Pose Tilted(const Eigen::Vector3d& center, double a0) {
  const Eigen::Quaterniond q(
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()));
  Pose pose{{center.x(), center.y(), center.z()}, {q.w(), q.x(), q.y(), q.z()}};
  pose.globals[kA0] = a0;
  return pose;
}

double Evaluate(const ceres::CostFunction& cost, const Pose& pose) {
  const double* parameters[] = {pose.center.data(), pose.quaternion.data(),
                                pose.globals.data()};
  double residual = 0.0;
  cost.Evaluate(parameters, &residual, nullptr);
  return residual;
}

// The apex at c + R (0, 0, a0 s), its height along the start's axis z0:
// zero at the start, sqrt(w) times the millimetres it moves along z0, blind
// to moves across it.
TEST(ApexGaugeResidualTest, ReadsTheApexsHeightAlongTheStartsAxis) {
  const double s = -0.5;  // a3 = 0.5 at u_min = -pi/2.
  const Pose start = Tilted({10.0, -4.0, 7.0}, 60.0);
  const Eigen::Quaterniond q(start.quaternion[0], start.quaternion[1],
                             start.quaternion[2], start.quaternion[3]);
  const Eigen::Vector3d axis = q * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d apex =
      Eigen::Vector3d(start.center.data()) + axis * (60.0 * s);
  std::unique_ptr<ceres::CostFunction> cost(
      ApexGaugeResidual::Create(2.0, s, axis, axis.dot(apex)));
  EXPECT_NEAR(Evaluate(*cost, start), 0.0, 1e-12);
  Pose moved = start;
  for (int i = 0; i < 3; ++i) moved.center[i] += 1.5 * axis[i];
  EXPECT_NEAR(Evaluate(*cost, moved), 3.0, 1e-12);
  const Eigen::Vector3d across = axis.unitOrthogonal();
  moved = start;
  for (int i = 0; i < 3; ++i) moved.center[i] += 4.0 * across[i];
  EXPECT_NEAR(Evaluate(*cost, moved), 0.0, 1e-12);
  // A shorter model (a0 60 -> 56 mm) lifts the apex by 4 |s| = 2 mm.
  moved = start;
  moved.globals[kA0] = 56.0;
  EXPECT_NEAR(Evaluate(*cost, moved), 4.0, 1e-12);
}

TEST(ApexGaugeResidualTest, JacobianPassesTheGradientChecker) {
  const Pose pose = Tilted({3.0, 2.0, -1.0}, 45.0);
  std::unique_ptr<ceres::CostFunction> cost(ApexGaugeResidual::Create(
      1.7, -0.6, Eigen::Vector3d(0.2, 0.1, 1.0).normalized(), 12.0));
  ceres::QuaternionManifold manifold;
  std::vector<const ceres::Manifold*> manifolds = {nullptr, &manifold, nullptr};
  ceres::NumericDiffOptions numeric;
  ceres::GradientChecker checker(cost.get(), &manifolds, numeric);
  const double* parameters[] = {pose.center.data(), pose.quaternion.data(),
                                pose.globals.data()};
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
}

}  // namespace
}  // namespace pfdm
