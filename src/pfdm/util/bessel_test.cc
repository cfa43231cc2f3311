#include "pfdm/util/bessel.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// The series against glibc's j0 and j1 (which ceres::BesselJ0 calls) on
// 40,001 points of [-2, 2], 0 and the ends included, and past it, where
// glibc answers.
TEST(BesselTest, TheSeriesMatchesGlibcToRoundOff) {
  double worst = 0.0;
  for (int i = -20000; i <= 20000; ++i) {
    const double x = i * 1e-4;
    const BesselJ01 j = BesselJ0J1(x);
    worst = std::max(worst, std::abs(j.j0 - j0(x)));
    worst = std::max(worst, std::abs(j.j1 - j1(x)));
  }
  EXPECT_LT(worst, 4e-16);
  EXPECT_EQ(BesselJ0J1(0.0).j0, 1.0);
  EXPECT_EQ(BesselJ0J1(0.0).j1, 0.0);
  for (double x : {2.0000001, -3.0, 10.0}) {
    EXPECT_EQ(BesselJ0J1(x).j0, j0(x));
    EXPECT_EQ(BesselJ0J1(x).j1, j1(x));
  }
  // J1 is odd, J0 even, exactly.
  EXPECT_EQ(BesselJ0J1(-1.3).j1, -BesselJ0J1(1.3).j1);
  EXPECT_EQ(BesselJ0J1(-1.3).j0, BesselJ0J1(1.3).j0);
}

}  // namespace
}  // namespace pfdm
