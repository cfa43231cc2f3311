#include "pfdm/model/parameter_function.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

// Span counts knots where it once searched them: the same span as a
// binary search (std::upper_bound) everywhere, on the knots themselves,
// just beside them and at the ends.
TEST(KnotGridTest, SpanIsTheBinarySearchsSpan) {
  const KnotGrid grid(17, -2.4, 0.3);
  std::vector<double> u_values = {-9.0, 9.0};
  for (int k = 0; k < grid.num_knots(); ++k) {
    const double knot = grid.KnotU(k);
    for (double u :
         {knot, std::nextafter(knot, -10.0), std::nextafter(knot, 10.0)}) {
      u_values.push_back(u);
    }
  }
  for (int i = 0; i <= 1000; ++i) u_values.push_back(-2.4 + 2.7 * i / 1000);
  std::vector<double> knots;
  for (int k = 0; k < grid.num_knots(); ++k) knots.push_back(grid.KnotU(k));
  for (double u : u_values) {
    const double clamped = std::clamp(u, -2.4, 0.3);
    const int searched = std::clamp(
        static_cast<int>(std::upper_bound(knots.begin(), knots.end(), clamped) -
                         knots.begin()) -
            1,
        0, grid.num_knots() - 2);
    EXPECT_EQ(grid.Span(u).k0, searched) << "u = " << u;
  }
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
