#include "pfdm/util/batch_trig.h"

#include <cmath>
#include <random>
#include <vector>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(BatchTrigTest, MatchesTheScalarFunctions) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> angle(-8.0, 8.0);
  std::vector<double> angles = {0.0, -0.0, M_PI / 2, -M_PI, 1e-300, 123.456};
  for (int i = 0; i < 37; ++i) angles.push_back(angle(random));
  for (int n : {0, 1, 3, 4, 5, static_cast<int>(angles.size())}) {
    std::vector<double> sines(n, 7.0), cosines(n, 7.0);
    SinCosMany(angles.data(), n, sines.data(), cosines.data());
    for (int i = 0; i < n; ++i) {
      // libmvec promises 4 ulp; these are absolute bounds for |value| <= 1.
      EXPECT_NEAR(sines[i], std::sin(angles[i]), 1e-15) << angles[i];
      EXPECT_NEAR(cosines[i], std::cos(angles[i]), 1e-15) << angles[i];
    }
  }
}

// A point's shape must not depend on where it sits in its group, so an
// angle gives the same bits wherever it is in the batch.
TEST(BatchTrigTest, AnAngleGivesTheSameBitsAnywhereInTheBatch) {
  const double x = 0.7391;
  double alone_sin, alone_cos;
  SinCosMany(&x, 1, &alone_sin, &alone_cos);
  for (int n = 1; n <= 9; ++n) {
    for (int at = 0; at < n; ++at) {
      std::vector<double> angles(n, -2.5), sines(n), cosines(n);
      angles[at] = x;
      SinCosMany(angles.data(), n, sines.data(), cosines.data());
      EXPECT_EQ(sines[at], alone_sin) << n << " " << at;
      EXPECT_EQ(cosines[at], alone_cos) << n << " " << at;
    }
  }
}

}  // namespace
}  // namespace pfdm
