// fit.json's not_measured section: which numbers are null because the data
// cannot determine them, and why (FitAnalysis::rotation_measured,
// level_extrapolated).
#ifndef PFDM_IO_NOT_MEASURED_JSON_H_
#define PFDM_IO_NOT_MEASURED_JSON_H_

#include "nlohmann/json.hpp"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// {"frames": the frames without a measured turn about the axis,
//  "definition"} when there are such frames, and "extrapolated": {"levels"
//  ("basal", "mid", "apical", "apex cap"), "apex_ring", "shown",
//  "definition"} when frame 0's data do not reach the apex, "short_span"
//  and "walls_unseen": {"frames", "definition"} when frames have no volume
//  for either reason (FitAnalysis::volume_measured, walls_measured); null
//  when every number is measured.
nlohmann::ordered_json NotMeasured(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_IO_NOT_MEASURED_JSON_H_
