#include "pfdm/fit/residuals/data_cost.h"

#include <memory>

#include "gtest/gtest.h"
#include "pfdm/model/model.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(DataCostTest, NamesRoundTripAndUnknownNamesAreErrors) {
  for (JacobianKind kind : {JacobianKind::kAnalytic, JacobianKind::kAutodiff,
                            JacobianKind::kNumeric}) {
    EXPECT_EQ(JacobianFromName(JacobianName(kind)), kind);
  }
  EXPECT_THROW(JacobianFromName("symbolic"), InputError);
}

TEST(DataCostTest, AllThreeKindsGiveTheSameResidualAndJacobian) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 40.0;
  f[kB0] = 1.0;
  f[kTau] = 0.1;
  double center[3] = {1, 2, 3}, q[4] = {1, 0, 0, 0};
  const double* parameters[] = {center, q, f.data(), f.data(), f.data()};
  double residual[3][3], jacobian[3][3 * kNumFunctions];
  int i = 0;
  for (JacobianKind kind : {JacobianKind::kAnalytic, JacobianKind::kAutodiff,
                            JacobianKind::kNumeric}) {
    std::unique_ptr<ceres::CostFunction> cost(
        MakePointCost(Eigen::Vector3d(1, 1, 1), -0.3, 0.7, 0.25,
                      ModelConfig::Paper(17).FreeMask(), true, kind));
    double* jacobians[5] = {nullptr, nullptr, nullptr, jacobian[i], nullptr};
    ASSERT_TRUE(cost->Evaluate(parameters, residual[i], jacobians));
    ++i;
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(residual[0][k], residual[1][k]);
    EXPECT_DOUBLE_EQ(residual[0][k], residual[2][k]);
  }
  for (int k = 0; k < 3 * kNumFunctions; ++k) {
    EXPECT_NEAR(jacobian[0][k], jacobian[1][k], 1e-12);
    EXPECT_NEAR(jacobian[0][k], jacobian[2][k], 1e-6);
  }
}

}  // namespace
}  // namespace pfdm
