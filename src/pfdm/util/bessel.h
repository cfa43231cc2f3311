// The Bessel functions J0 and J1 of the bend's ring term (model/
// global_deformations.h), for the closed-form shapes that evaluate them at
// every data point: glibc's j0 and j1 were 3.5 % of a contour job.
#ifndef PFDM_UTIL_BESSEL_H_
#define PFDM_UTIL_BESSEL_H_

#include <cmath>

namespace pfdm {

struct BesselJ01 {
  double j0, j1;
};

namespace internal {

// (-1)^k / (k!)^2 and (-1)^k / (k! (k + 1)!), k = 0..16.
struct BesselSeries {
  static constexpr int kTerms = 17;
  double j0[kTerms] = {}, j1[kTerms] = {};
};

constexpr BesselSeries MakeBesselSeries() {
  BesselSeries series;
  double factorial = 1.0, sign = 1.0;  // k!, exact in a double to k = 18.
  for (int k = 0; k < BesselSeries::kTerms; ++k) {
    series.j0[k] = sign / (factorial * factorial);
    series.j1[k] = sign / (factorial * factorial * (k + 1));
    factorial *= k + 1;
    sign = -sign;
  }
  return series;
}

inline constexpr BesselSeries kBesselSeries = MakeBesselSeries();

}  // namespace internal

// J0(x) = sum_k (-1)^k t^k / (k!)^2 and J1(x) = (x / 2) sum_k (-1)^k t^k /
// (k! (k + 1)!), t = x^2 / 4, summed to k = 16 by Horner's rule for
// |x| <= 2 (t <= 1: the first term left out is under 1e-28, the sums'
// round-off a few 1e-16).  The bend's argument, pi/2 a Cu^e1 with a <= 1,
// stays under pi/2; anything larger goes to glibc.
inline BesselJ01 BesselJ0J1(double x) {
  if (!(std::abs(x) <= 2.0)) return {j0(x), j1(x)};
  const internal::BesselSeries& series = internal::kBesselSeries;
  constexpr int kLast = internal::BesselSeries::kTerms - 1;
  const double t = 0.25 * x * x;
  double s0 = series.j0[kLast], s1 = series.j1[kLast];
  for (int k = kLast - 1; k >= 0; --k) {
    s0 = s0 * t + series.j0[k];
    s1 = s1 * t + series.j1[k];
  }
  return {s0, 0.5 * x * s1};
}

}  // namespace pfdm

#endif  // PFDM_UTIL_BESSEL_H_
