// The error pfdm raises for bad input: files, data, options, failed solves.
#ifndef PFDM_UTIL_ERROR_H_
#define PFDM_UTIL_ERROR_H_

#include <stdexcept>
#include <string>

namespace pfdm {

// what() is one line naming the file and line, or the frame, at fault, e.g.
// "points.csv:12: column 'x' is not a finite number".  The CLI prints it and
// exits non-zero.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message)
      : std::runtime_error(message) {}
};

}  // namespace pfdm

#endif  // PFDM_UTIL_ERROR_H_
