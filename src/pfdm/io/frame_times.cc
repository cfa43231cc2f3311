#include "pfdm/io/frame_times.h"

#include <sstream>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// 33.3 as written, not 33.299999999999997.
std::string Show(double ms) {
  std::ostringstream out;
  out << ms;
  return out.str();
}

std::string At(const std::string& path, unsigned line) {
  return path + ":" + std::to_string(line) + ": ";
}

}  // namespace

void FrameTimes::Add(const std::string& path, unsigned line, long long frame,
                     double ms) {
  if (ms < 0.0) {
    throw InputError(At(path, line) + "time_ms " + Show(ms) + " is negative");
  }
  const auto [it, first] = first_.emplace(frame, std::make_pair(ms, line));
  if (!first && it->second.first != ms) {
    throw InputError(At(path, line) + "time_ms " + Show(ms) +
                     " differs from frame " + std::to_string(frame) + "'s " +
                     Show(it->second.first) + " (line " +
                     std::to_string(it->second.second) + ")");
  }
}

std::vector<double> FrameTimes::Times(const std::string& path) const {
  std::vector<double> times;
  for (const auto& [frame, entry] : first_) {
    if (!times.empty() && !(entry.first > times.back())) {
      throw InputError(At(path, entry.second) + "frame " +
                       std::to_string(frame) + "'s time_ms " +
                       Show(entry.first) + " is not after frame " +
                       std::to_string(frame - 1) + "'s " + Show(times.back()));
    }
    times.push_back(entry.first);
  }
  return times;
}

}  // namespace pfdm
