#include "pfdm/fit/residuals/free_entries.h"

#include <memory>
#include <vector>

#include "ceres/gradient_checker.h"
#include "gtest/gtest.h"
#include "pfdm/fit/residuals/regularizer.h"

namespace pfdm {
namespace {

FunctionValues Ramp(double start) {
  FunctionValues values;
  for (int f = 0; f < kNumFunctions; ++f) values[f] = start + 0.1 * f;
  return values;
}

TEST(FreeEntriesTest, KeepsHeldEntriesAndStoresFreeOnes) {
  FunctionValues whole = Ramp(1.0);
  FreeEntries entries(whole.data(), {kA1, kTau});
  ASSERT_EQ(entries.size(), 2);
  EXPECT_EQ(entries.parameters()[0], whole[kA1]);
  EXPECT_EQ(entries.parameters()[1], whole[kTau]);
  EXPECT_EQ(entries.IndexOf(kTau), 1);
  EXPECT_EQ(entries.IndexOf(kA0), -1);

  const double moved[2] = {7.0, 8.0};
  FunctionValues expanded{};
  entries.Expand(moved, expanded.data());
  for (int f = 0; f < kNumFunctions; ++f) {
    const double expected = f == kA1 ? 7.0 : f == kTau ? 8.0 : whole[f];
    EXPECT_EQ(expanded[f], expected) << FunctionName(f);
  }
  entries.parameters()[1] = -3.0;
  entries.Store();
  EXPECT_EQ(whole[kTau], -3.0);
  EXPECT_EQ(whole[kA1], 1.1);
  EXPECT_EQ(whole[kA2], 1.2);
}

TEST(FreeEntriesCostTest, GivesTheFreeColumnsOfTheWholeJacobian) {
  FunctionValues scales = Ramp(1.0), prior = Ramp(0.0);
  FunctionValues first = Ramp(0.5), second = Ramp(-0.5);
  FreeEntries entries(first.data(), {kA2, kB1, kE2o});
  std::unique_ptr<ceres::CostFunction> whole(
      SmoothnessResidual::Create(2.0, scales));
  // Blocks: first (compact), second (whole), first again as the third.
  FunctionValues third = first;
  FreeEntriesCost compact(SmoothnessResidual::Create(2.0, scales),
                          {&entries, nullptr, nullptr});
  ASSERT_EQ(compact.parameter_block_sizes()[0], 3);
  ASSERT_EQ(compact.parameter_block_sizes()[1], kNumFunctions);

  entries.parameters()[1] = 0.25;  // b1 moves.
  FunctionValues first_moved = first;
  first_moved[kB1] = 0.25;
  const double* whole_parameters[] = {first_moved.data(), second.data(),
                                      third.data()};
  const double* compact_parameters[] = {entries.parameters(), second.data(),
                                        third.data()};
  double whole_residuals[kNumFunctions], compact_residuals[kNumFunctions];
  double whole_jacobian[kNumFunctions * kNumFunctions];
  double compact_jacobian[kNumFunctions * 3];
  double* whole_jacobians[] = {whole_jacobian, nullptr, nullptr};
  double* compact_jacobians[] = {compact_jacobian, nullptr, nullptr};
  ASSERT_TRUE(
      whole->Evaluate(whole_parameters, whole_residuals, whole_jacobians));
  ASSERT_TRUE(compact.Evaluate(compact_parameters, compact_residuals,
                               compact_jacobians));
  for (int r = 0; r < kNumFunctions; ++r) {
    EXPECT_EQ(compact_residuals[r], whole_residuals[r]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(compact_jacobian[3 * r + c],
                whole_jacobian[kNumFunctions * r + entries.free()[c]]);
    }
  }
  EXPECT_NE(compact_jacobian[3 * kB1 + 1], 0.0);

  ceres::NumericDiffOptions numeric;
  const std::vector<const ceres::Manifold*> manifolds(3, nullptr);
  ceres::GradientChecker checker(&compact, &manifolds, numeric);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(compact_parameters, 1e-9, &results))
      << results.error_log;
}

}  // namespace
}  // namespace pfdm
