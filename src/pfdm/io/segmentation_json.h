// fit.json's "segmentation": the label map a fit's points came from, the
// labels read as which structure, and what was found in it.
#ifndef PFDM_IO_SEGMENTATION_JSON_H_
#define PFDM_IO_SEGMENTATION_JSON_H_

#include "nlohmann/json.hpp"
#include "pfdm/segmentation/segmentation_record.h"

namespace pfdm {

// {"source", "labels": {"lv", "myo", "rv" (null: none)}, "slices",
//  "frames", "voxel_mm": [i, j, slice], "geometry", "apex_slice",
//  "base_slice" and "slices_fitted" per frame, "rv_insertion_slices",
//  "misaligned": [{"slice", "frames", "max_offset_mm"}]}.
nlohmann::ordered_json SegmentationJson(const SegmentationRecord& record);

}  // namespace pfdm

#endif  // PFDM_IO_SEGMENTATION_JSON_H_
