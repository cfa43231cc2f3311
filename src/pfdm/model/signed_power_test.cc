#include "pfdm/model/signed_power.h"

#include <cmath>

#include "ceres/jet.h"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

using Jet2 = ceres::Jet<double, 2>;

TEST(SignedPowerTest, MatchesSignTimesPowerAwayFromZero) {
  for (double x : {-0.9, -0.3, 0.01, 0.5, 1.0}) {
    for (double e : {0.3, 1.0, 1.7}) {
      const double expected = std::copysign(std::pow(std::abs(x), e), x);
      EXPECT_NEAR(SignedPower(x, e), expected, 1e-9) << x << " " << e;
    }
  }
}

TEST(SignedPowerTest, IsExactlyTheIdentityAtUnitExponent) {
  for (double x : {-0.7, -1e-12, 0.0, 1e-12, 0.4}) {
    EXPECT_EQ(SignedPower(x, 1.0), x);
  }
}

// pow(|x|, e) of a Jet at x = 0 has an infinite or NaN derivative; the
// smooth form must give finite ones in both x and e.
TEST(SignedPowerTest, DerivativesAreFiniteAtZero) {
  for (double e : {0.5, 1.0, 2.0}) {
    const Jet2 value = SignedPower(Jet2(0.0, 0), Jet2(e, 1));
    EXPECT_EQ(value.a, 0.0);
    EXPECT_TRUE(std::isfinite(value.v[0])) << e;
    EXPECT_EQ(value.v[1], 0.0);  // d/de of 0 * anything.
    EXPECT_NEAR(value.v[0], std::pow(kSignedPowerDelta, e - 1.0),
                1e-9 * std::pow(kSignedPowerDelta, e - 1.0));
  }
}

TEST(SignedPowerTest, ExponentDerivativeMatchesLogFormula) {
  const double x = 0.6, e = 1.3;
  const Jet2 value = SignedPower(Jet2(x), Jet2(e, 1));
  EXPECT_NEAR(value.v[1], std::pow(x, e) * std::log(x), 1e-9);
}

}  // namespace
}  // namespace pfdm
