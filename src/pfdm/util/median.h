// The median of a sample: its upper middle value for an even count (no
// mean of two, so that it is always one of the values), 0 for none.
#ifndef PFDM_UTIL_MEDIAN_H_
#define PFDM_UTIL_MEDIAN_H_

#include <algorithm>
#include <vector>

namespace pfdm {

inline double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace pfdm

#endif  // PFDM_UTIL_MEDIAN_H_
