#include "pfdm/io/mesh_fields.h"

#include <charconv>
#include <cmath>

#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {

double ToNumber(const std::string& where, const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || rest != end || text.empty()) {
    throw InputError(where + ": '" + Clip(text) + "' is not a number");
  }
  if (!std::isfinite(value)) throw InputError(where + ": not a finite number");
  return value;
}

double CheckCoordinate(const std::string& where, double value,
                       const std::string& text) {
  if (std::abs(value) > kMaxCoordinateMm) {
    throw InputError(where + ": coordinate '" + Clip(text) +
                     "' is out of range (more than 1e6 mm from the origin)");
  }
  return value;
}

double ToCoordinate(const std::string& where, const std::string& text) {
  return CheckCoordinate(where, ToNumber(where, text), text);
}

long long ToInteger(const std::string& where, const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || rest != end || text.empty()) {
    throw InputError(where + ": '" + Clip(text) + "' is not an integer");
  }
  return value;
}

void AddFan(const std::string& where, const std::vector<long long>& polygon,
            size_t num_points, TriangleMesh* mesh) {
  for (long long index : polygon) {
    if (index < 0 || index >= static_cast<long long>(num_points)) {
      throw InputError(where + ": vertex " + std::to_string(index) +
                       " out of range");
    }
  }
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    mesh->triangles.push_back({static_cast<int>(polygon[0]),
                               static_cast<int>(polygon[i]),
                               static_cast<int>(polygon[i + 1])});
  }
}

}  // namespace pfdm
