// fit.json's account of where the segments are: whether they are the AHA's,
// anchored to the RV insertion, and why not; the apex cap's coverage.
#ifndef PFDM_IO_SEGMENTS_JSON_H_
#define PFDM_IO_SEGMENTS_JSON_H_

#include "nlohmann/json.hpp"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// {"anatomical": bool, "anchor": where the insertion came from or why the
//  segments are not anatomical, "definition", and when anatomical
//  "rv_insertion": {"anterior_v_deg", "inferior_v_deg" (null when
//  unknown), "septal_arc_deg", "anterior_points", "inferior_points",
//  "direction"}; "apex_cap": {"height_fraction", "measured", "reason"}}.
nlohmann::ordered_json SegmentsSection(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_IO_SEGMENTS_JSON_H_
