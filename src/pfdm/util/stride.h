// Taking every stride-th of many items to keep at most so many of them: a
// frame's points for a check, a k-d tree's sample, a mean over pairs.
#ifndef PFDM_UTIL_STRIDE_H_
#define PFDM_UTIL_STRIDE_H_

#include <algorithm>
#include <cstddef>

namespace pfdm {

// The least stride that keeps at most `most` (at least 1) of `count` items
// when every stride-th is taken from the first: 1 when all fit.
inline size_t StrideForAtMost(size_t count, size_t most) {
  most = std::max<size_t>(most, 1);
  return std::max<size_t>(1, (count + most - 1) / most);
}

}  // namespace pfdm

#endif  // PFDM_UTIL_STRIDE_H_
