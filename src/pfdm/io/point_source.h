// Reads points by the file's kind: pfdm's CSV or biv-me guide points.
#ifndef PFDM_IO_POINT_SOURCE_H_
#define PFDM_IO_POINT_SOURCE_H_

#include <string>

#include "pfdm/util/point_data.h"

namespace pfdm {

// format "csv", "gpfile" or "auto": a folder or a file named GPFile* is
// biv-me guide points (keeping the contour types `contours` lists, with the
// lv-endo and lv-epi aliases), anything else CSV.  Throws InputError.
PointSequence ReadPoints(const std::string& path, const std::string& format,
                         const std::string& contours);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_SOURCE_H_
