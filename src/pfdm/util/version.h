// pfdm's version, one source for the CLI, fit.json, the report and Python:
// CMake's project version, given to version.cc alone so that a release
// recompiles one file.
#ifndef PFDM_UTIL_VERSION_H_
#define PFDM_UTIL_VERSION_H_

#include <string>

namespace pfdm {

// "0.1.0".
const char* PfdmVersion();

// The current time in UTC as "2026-12-02 02:10 UTC": when a report was made.
std::string UtcMinuteNow();

}  // namespace pfdm

#endif  // PFDM_UTIL_VERSION_H_
