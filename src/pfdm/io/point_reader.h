// Reads point sequences: pfdm's CSV and biv-me guide-point files.
#ifndef PFDM_IO_POINT_READER_H_
#define PFDM_IO_POINT_READER_H_

#include <string>
#include <vector>

#include "pfdm/util/point_data.h"

namespace pfdm {

// CSV with a header naming at least frame,id,x,y,z (any order; other
// columns ignored).  Frames must run 0..F-1 with none empty and no id twice
// in a frame.  Throws InputError "PATH:LINE: ..." or "PATH: frame N: ...".
PointSequence ReadPointsCsv(const std::string& path);

// biv-me guide points, tab-separated with header `x y z contour type frameID
// weight time frame`: one file (one frame), or a folder of GPFile_*.txt, one
// frame per file in name order, as biv-me writes them.  The `time frame`
// column is not read: biv-me's own files carry 1.0 there on some LAX rows.
// Only rows whose contour type is listed are kept (all when the list is
// empty); each is an untracked point with an id of its own.  Throws
// InputError "PATH: no points of contour types A,B" when the filter keeps
// nothing at all, and "FILE: frame N: ..." when it empties one frame.
PointSequence ReadGpFiles(const std::string& path,
                          const std::vector<std::string>& contour_types);

// Splits a comma-separated list, expanding lv-endo and lv-epi into the SAX
// and LAX contour types, and lv-cavity into lv-endo and the aortic valve
// points: the cavity runs up the outflow tract to that valve, where the
// basal contours leave it between the long-axis planes.  The mitral valve
// points are not in it: they close the cavity (MitralValvePlanes), and
// fitted as surface points where the annulus dips below the rim they pull
// the basal wall inward.
std::vector<std::string> ExpandContourAlias(const std::string& spec);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_READER_H_
