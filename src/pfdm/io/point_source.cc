#include "pfdm/io/point_source.h"

#include <filesystem>

#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

namespace pfdm {

PointFormat PointFormatOf(const std::string& path, const std::string& format) {
  if (format == "csv") return PointFormat::kCsv;
  if (format == "gpfile") return PointFormat::kGpFile;
  if (format != "auto") {
    throw InputError("unknown --format '" + format +
                     "' (expected csv, gpfile or auto)");
  }
  const std::filesystem::path p(path);
  return std::filesystem::is_directory(p) ||
                 p.filename().string().rfind("GPFile", 0) == 0
             ? PointFormat::kGpFile
             : PointFormat::kCsv;
}

PointSequence ReadPoints(const std::string& path, const std::string& format,
                         const std::string& contours) {
  if (PointFormatOf(path, format) == PointFormat::kCsv) {
    return ReadPointsCsv(path);
  }
  return ReadGpFiles(path, ExpandContourAlias(contours));
}

}  // namespace pfdm
