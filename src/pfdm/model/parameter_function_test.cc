#include "pfdm/model/parameter_function.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(KnotGridTest, KnotsAreEquallySpacedAlongTheAxis) {
  const KnotGrid grid(5, -M_PI / 2, M_PI / 6);
  EXPECT_DOUBLE_EQ(grid.KnotU(0), -M_PI / 2);
  EXPECT_DOUBLE_EQ(grid.KnotU(4), M_PI / 6);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(std::sin(grid.KnotU(k)), -1.0 + 1.5 * k / 4, 1e-12);
  }
}

TEST(KnotGridTest, SpanWeightsAreLinearInU) {
  const KnotGrid grid(5, -M_PI / 2, M_PI / 6);
  const double u = 0.75 * grid.KnotU(1) + 0.25 * grid.KnotU(2);
  KnotSpan span = grid.Span(u);
  EXPECT_EQ(span.k0, 1);
  EXPECT_NEAR(span.weight, 0.25, 1e-12);
  span = grid.Span(grid.KnotU(2));
  EXPECT_NEAR(span.k0 + span.weight, 2.0, 1e-12);
  span = grid.Span(M_PI / 6);  // The last span, not a span past the end.
  EXPECT_EQ(span.k0, 3);
  EXPECT_DOUBLE_EQ(span.weight, 1.0);
  span = grid.Span(-7.0);  // Clamped.
  EXPECT_EQ(span.k0, 0);
  EXPECT_DOUBLE_EQ(span.weight, 0.0);
}

TEST(FunctionNameTest, NamesRoundTrip) {
  for (int f = 0; f < kNumFunctions; ++f) {
    EXPECT_EQ(FunctionFromName(FunctionName(f)), f);
  }
  EXPECT_EQ(FunctionFromName("tau"), kTau);
  EXPECT_EQ(FunctionFromName("nope"), -1);
}

}  // namespace
}  // namespace pfdm
