#include "pfdm/fit/residuals/point_group_residual.h"

#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/point_group_checks.h"

namespace pfdm {
namespace {

// Knots that free different functions take the stacked rows' route.
TEST(PointGroupResidualTest, SquareRootFormOfUnlikeKnots) {
  std::vector<int> fewer = FreeFunctions();
  fewer.erase(fewer.begin() + 2);
  ExpectStackedNormalEquations(
      {{false, true, false, true, true}, {}, FreeFunctions(), fewer});
  ExpectStackedNormalEquations(
      {{false, false, false, false, true}, {}, {}, FreeFunctions()});
}

// Too few rows to gain from the square-root form: the rows themselves.
TEST(PointGroupResidualTest, SmallGroupsGiveTheirRows) {
  const FunctionMask mask = ModelConfig::Paper(17).FreeMask();
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  double center[3] = {1, 2, 3};
  double quaternion[4] = {1, 0, 0, 0};
  const PointSample sample(Eigen::Vector3d(10, 20, 5), 0.3, 1.1, 0.4);
  const PointGroupResidual group({sample, sample}, mask, true);
  EXPECT_FALSE(group.compressed());
  AnalyticPointResidual single(sample, mask, true);
  const double* parameters[] = {center, quaternion, f.data(), f.data(),
                                f.data()};
  double grouped[6], alone[3];
  ASSERT_TRUE(group.Evaluate(parameters, grouped, nullptr));
  ASSERT_TRUE(single.Evaluate(parameters, alone, nullptr));
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(grouped[i], alone[i]);
    EXPECT_EQ(grouped[3 + i], alone[i]);
  }
}

}  // namespace
}  // namespace pfdm
