#include "pfdm/io/point_source.h"

#include <filesystem>

#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

namespace pfdm {

PointSequence ReadPoints(const std::string& path, const std::string& format,
                         const std::string& contours) {
  std::string kind = format;
  if (kind == "auto") {
    const std::filesystem::path p(path);
    kind = std::filesystem::is_directory(p) ||
                   p.filename().string().rfind("GPFile", 0) == 0
               ? "gpfile"
               : "csv";
  }
  if (kind == "csv") return ReadPointsCsv(path);
  if (kind == "gpfile") return ReadGpFiles(path, ExpandContourAlias(contours));
  throw InputError("unknown --format '" + format +
                   "' (expected csv, gpfile or auto)");
}

}  // namespace pfdm
