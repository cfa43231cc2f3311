#include "pfdm/util/version.h"

#include <ctime>

#ifndef PFDM_VERSION
#define PFDM_VERSION "unknown"
#endif

namespace pfdm {

const char* PfdmVersion() { return PFDM_VERSION; }

std::string UtcMinuteNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

}  // namespace pfdm
