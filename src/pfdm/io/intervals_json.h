// fit.json's 95 % intervals: with --uncertainty on, "<key>_ci95": [low,
// high] beside every clinical, strain and segment number (a list of them
// beside a per-frame list; null where the number is), value -+ 1.96 sd
// from the delta method (report/number_uncertainty.h).
#ifndef PFDM_IO_INTERVALS_JSON_H_
#define PFDM_IO_INTERVALS_JSON_H_

#include "nlohmann/json.hpp"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// What the intervals are and how they were found.
extern const char* const kUncertaintyDefinition;

// Adds the intervals to fit.json's document (FitJson's sections written);
// nothing when analysis.sd was not computed.
void AddIntervals(const FitAnalysis& analysis,
                  nlohmann::ordered_json* document);

}  // namespace pfdm

#endif  // PFDM_IO_INTERVALS_JSON_H_
