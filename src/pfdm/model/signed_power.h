// sgn(x) |x|^e written so that it and its derivatives stay finite at x = 0.
#ifndef PFDM_MODEL_SIGNED_POWER_H_
#define PFDM_MODEL_SIGNED_POWER_H_

#include <cmath>

namespace pfdm {

// Smoothing of |x| near 0: below this the power is evaluated on
// sqrt(x^2 + delta^2).  Relative error elsewhere is about (e-1)/2 (delta/x)^2.
constexpr double kSignedPowerDelta = 1e-6;

// x (x^2 + delta^2)^((e-1)/2): equals sgn(x)|x|^e up to the smoothing, is
// exactly x at e = 1, and unlike pow(|x|, e) its derivatives in x and e are
// finite at x = 0, where pow of a Jet returns NaN.
template <typename T, typename E>
T SignedPower(const T& x, const E& e) {
  using std::pow;
  return x *
         pow(x * x + kSignedPowerDelta * kSignedPowerDelta, (e - 1.0) * 0.5);
}

}  // namespace pfdm

#endif  // PFDM_MODEL_SIGNED_POWER_H_
