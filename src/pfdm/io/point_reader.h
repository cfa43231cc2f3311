// Reads point sequences: pfdm's CSV and biv-me guide-point files.
#ifndef PFDM_IO_POINT_READER_H_
#define PFDM_IO_POINT_READER_H_

#include <string>
#include <vector>

#include "pfdm/util/point_data.h"

namespace pfdm {

// CSV with a header naming at least frame,id,x,y,z (any order; other
// columns ignored).  Frames must run 0..F-1 with none empty, no id twice
// in a frame and no point far from the others (CheckPointsLieTogether).
// Throws InputError "PATH:LINE: ..." or "PATH: frame N: ...".
PointSequence ReadPointsCsv(const std::string& path);

// biv-me guide points, tab-separated with header `x y z contour type frameID
// weight time frame`: one file (one frame), or a folder of GPFile_*.txt, one
// frame per file in name order, as biv-me writes them.  Only rows whose
// contour type is listed are kept (all when the list is empty); each is an
// untracked point with an id of its own.  x, y, z and contour type are
// required; frameID, weight and time frame are checked when present: a
// weight a finite number >= 0, a time frame a whole number, one per file
// (biv-me's 1.0 on one long-axis slice's rows is a label, not a frame); no
// kept point may lie far from the others (CheckPointsLieTogether).
// Throws InputError "FILE:LINE: column ..." for a bad row, "FILE: holds 3
// time frames ..." for a file of several, and unless empty_frames is kAllow,
// "PATH: no points of contour types A,B" when the filter keeps nothing at
// all and "FILE: frame N: ..." when it empties one frame.
enum class EmptyFrames { kRefuse, kAllow };
PointSequence ReadGpFiles(const std::string& path,
                          const std::vector<std::string>& contour_types,
                          EmptyFrames empty_frames = EmptyFrames::kRefuse);

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
