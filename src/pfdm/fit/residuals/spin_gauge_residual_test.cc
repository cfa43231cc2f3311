#include "pfdm/fit/residuals/spin_gauge_residual.h"

#include <cmath>
#include <memory>

#include "Eigen/Geometry"
#include "ceres/gradient_checker.h"
#include "ceres/manifold.h"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

std::array<double, 4> Wxyz(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

double Evaluate(const ceres::CostFunction& cost, std::array<double, 4> q) {
  const double* parameters[] = {q.data()};
  double residual = 0.0;
  cost.Evaluate(parameters, &residual, nullptr);
  return residual;
}

TEST(SpinGaugeResidualTest, ZeroForTiltsAndProportionalToSpin) {
  const Eigen::Quaterniond q0(
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()));
  std::unique_ptr<ceres::CostFunction> cost(
      SpinGaugeResidual::Create(1.0, 10.0, Wxyz(q0)));
  EXPECT_NEAR(Evaluate(*cost, Wxyz(q0)), 0.0, 1e-15);
  // A tilt about any axis normal to frame 0's z: no spin.
  for (double angle : {0.05, 0.3}) {
    const Eigen::Quaterniond tilted =
        q0 * Eigen::AngleAxisd(angle, Eigen::Vector3d(0.6, 0.8, 0.0));
    EXPECT_NEAR(Evaluate(*cost, Wxyz(tilted)), 0.0, 1e-14);
  }
  // A spin about frame 0's z: 2 rho sin(angle / 2) (and the sign follows).
  const Eigen::Quaterniond spun =
      q0 * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(Evaluate(*cost, Wxyz(spun)), 20.0 * std::sin(0.05), 1e-12);
  // Spin after a tilt (a swing-twist product) still reads.
  const Eigen::Quaterniond both =
      q0 * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitZ());
  EXPECT_LT(Evaluate(*cost, Wxyz(both)), -0.9);
}

TEST(SpinGaugeResidualTest, JacobianPassesTheGradientChecker) {
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()));
  std::unique_ptr<ceres::CostFunction> cost(
      SpinGaugeResidual::Create(3.0, 25.0, Wxyz(q0)));
  ceres::QuaternionManifold manifold;
  std::vector<const ceres::Manifold*> manifolds = {&manifold};
  ceres::NumericDiffOptions numeric;
  ceres::GradientChecker checker(cost.get(), &manifolds, numeric);
  std::array<double, 4> q =
      Wxyz(q0 * Eigen::Quaterniond(Eigen::AngleAxisd(
                    0.2, Eigen::Vector3d(1, 1, 1).normalized())));
  const double* parameters[] = {q.data()};
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
}

}  // namespace
}  // namespace pfdm
