// Wall time since a start, for the fit's and the solvers' accounts of where
// their time went.
#ifndef PFDM_UTIL_STOPWATCH_H_
#define PFDM_UTIL_STOPWATCH_H_

#include <chrono>

namespace pfdm {

using Clock = std::chrono::steady_clock;

inline double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace pfdm

#endif  // PFDM_UTIL_STOPWATCH_H_
