// Reads points by the file's kind: pfdm's CSV or biv-me guide points.
#ifndef PFDM_IO_POINT_SOURCE_H_
#define PFDM_IO_POINT_SOURCE_H_

#include <string>

#include "pfdm/util/point_data.h"

namespace pfdm {

enum class PointFormat { kCsv, kGpFile };

// format "csv", "gpfile" or "auto": a folder or a file named GPFile* is
// biv-me guide points, anything else CSV.  Throws InputError for another
// format.
PointFormat PointFormatOf(const std::string& path, const std::string& format);

// The points at path in PointFormatOf's format, keeping the guide points'
// contour types `contours` lists (with the lv-endo and lv-epi aliases).
// Throws InputError.
PointSequence ReadPoints(const std::string& path, const std::string& format,
                         const std::string& contours);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_SOURCE_H_
