// The long axis from landmarks in the data: biv-me guide points carry the
// apex (APEX_POINT) and the valves (MITRAL_VALVE, AORTA_VALVE), which say
// where the LV's axis runs whatever part of the wall the contours cover.
#ifndef PFDM_IO_LANDMARK_AXIS_H_
#define PFDM_IO_LANDMARK_AXIS_H_

#include <optional>
#include <string>

#include "pfdm/fit/fit_options.h"

namespace pfdm {

// Frame 0's file of the guide points at `path` (a folder of GPFile_*.txt,
// its first in name order, or one GPFile*); empty when they are not.
std::string FrameZeroGuidePoints(const std::string& path);

// From frame 0 of the guide points at `points` (a folder of GPFile_*.txt,
// its first file in name order, or one GPFile*): the APEX_POINTs' mean as
// the apex and the centroid of the MITRAL_VALVE and AORTA_VALVE points as
// the base's centre, source "APEX_POINT and MITRAL_VALVE" (", AORTA_VALVE"
// when there are some).  nullopt when `points` are not guide points, frame
// 0 lacks either landmark, or they lie within 1 mm of each other.
std::optional<AxisHint> LandmarkAxis(const std::string& points);

// Gives options->hint the landmarks' axis when it has none (--apex/--base
// come first).
void AddLandmarkAxis(const std::string& points, FitOptions* options);

}  // namespace pfdm

#endif  // PFDM_IO_LANDMARK_AXIS_H_
