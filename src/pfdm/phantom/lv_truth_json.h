// The analytic LV phantom's truth as JSON (`pfdm simulate --phantom lv`
// writes it beside the points as NAME_truth.json).
#ifndef PFDM_PHANTOM_LV_TRUTH_JSON_H_
#define PFDM_PHANTOM_LV_TRUTH_JSON_H_

#include <string>

#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {

// {"phantom": "lv", the options, "geometry", "design", "ring_heights",
//  "summary": {edv_ml, esv_ml, es_frame, ejection_fraction} (endocardial
//  cavity; ES the frame of least cavity volume), and "frames": per frame
//  the fields of LvFrameTruth (lv_truth.h): "progress", "rigid",
//  "world_from_body" (4 x 4, rows), "length_mm",
//  "longitudinal_shortening_percent", "apex_rotation_deg",
//  "base_rotation_deg", "net_twist_deg", "mean_radial_contraction_percent",
//  the volumes, "rings" {"midwall",
//  "endo", "epi"} each {"rotation_deg", "radial_contraction_percent"} per
//  ring height, "segments" (16, with "segment" and "name") and
//  "outlier_ids" (the tags moved as outliers in the frame)}; the options
//  include "outlier_fraction" and "outlier_mm" [min, max];
//  "rv_insertion": {"anterior", "inferior" (frame 0, world, mm),
//  "body_longitude_deg", "height_fraction", "definition"}.
std::string LvTruthJson(const LvPhantom& phantom);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_TRUTH_JSON_H_
