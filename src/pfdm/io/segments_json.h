// fit.json's account of where the segments are: whether they are the AHA's,
// anchored to the RV insertion, and why not; the apex cap's coverage; a
// solid's strain per layer of each segment.
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

// {"index": the dyssynchrony index (null with fewer than 2 segments),
//  "unit": "ms" or "frames", "segments": how many it is over,
//  "definition", "time_to_peak": per segment from ED (null where n/a),
//  "peak_frame": per segment (null where n/a)}: FitAnalysis::dyssynchrony.
nlohmann::ordered_json DyssynchronySection(const FitAnalysis& analysis);

// A solid's strain per layer of region r over the frames
// (FitAnalysis::region_layers, report/layer_strain.h): {"endocardium":
// {"ecc_percent", "ell_percent", "thickening_percent"}, "midwall": ...,
// "epicardium": ...}, each a list per frame, null where not measured.  Null
// without a wall.
nlohmann::ordered_json RegionLayersJson(const FitAnalysis& analysis, size_t r);

// Region r's Err across the wall per frame (null where not measured); null
// without a wall.
nlohmann::ordered_json RegionErrJson(const FitAnalysis& analysis, size_t r);

}  // namespace pfdm

#endif  // PFDM_IO_SEGMENTS_JSON_H_
