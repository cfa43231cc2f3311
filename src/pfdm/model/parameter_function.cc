#include "pfdm/model/parameter_function.h"

#include <algorithm>
#include <cmath>

#include "glog/logging.h"

namespace pfdm {
namespace {
constexpr const char* kNames[kNumFunctions] = {
    "a0", "a1",  "a2",  "a3",  "eps1", "eps2", "b0",   "b1",    "b2",
    "b3", "tau", "e1o", "e2o", "e3o",  "h",    "dtau", "shift", "squeeze"};
}  // namespace

const char* FunctionName(int function) {
  CHECK(function >= 0 && function < kNumFunctions);
  return kNames[function];
}

int FunctionFromName(const std::string& name) {
  for (int f = 0; f < kNumFunctions; ++f) {
    if (name == kNames[f]) return f;
  }
  return -1;
}

KnotGrid::KnotGrid(int num_knots, double u_min, double u_max)
    : num_knots_(num_knots), u_min_(u_min), u_max_(u_max) {
  CHECK_GE(num_knots, 1);
  CHECK_LT(u_min, u_max);
  if (num_knots == 1) {
    knot_u_.push_back(0.5 * (u_min + u_max));
    return;
  }
  const double s_min = std::sin(u_min), s_max = std::sin(u_max);
  for (int k = 0; k < num_knots; ++k) {
    knot_u_.push_back(std::asin(
        std::clamp(s_min + (s_max - s_min) * k / (num_knots - 1), -1.0, 1.0)));
  }
  knot_u_.front() = u_min;  // Exactly, whatever asin(sin(.)) rounds to.
  knot_u_.back() = u_max;
}

KnotSpan KnotGrid::Span(double u) const {
  KnotSpan span;
  if (num_knots_ == 1) return span;
  u = std::clamp(u, u_min_, u_max_);
  // The knots past the first at or below u, counted without a branch: the
  // span a binary search would find, exactly, and cheaper than the sine
  // that would place u on the grid.  This runs at every model evaluation,
  // where a data point's u is as good as random and a binary search
  // mispredicted about half of its steps (3.7 % of a 20,000-tag job).
  int knots_below = 0;
  for (int k = 1; k < num_knots_; ++k) knots_below += knot_u_[k] <= u;
  span.k0 = std::min(knots_below, num_knots_ - 2);
  const double u0 = KnotU(span.k0), u1 = KnotU(span.k0 + 1);
  span.weight = std::clamp((u - u0) / (u1 - u0), 0.0, 1.0);
  return span;
}

}  // namespace pfdm
