// The report's per-segment strain: each level's segments' Ecc over the
// cycle, their time to peak and the dyssynchrony index (segment_timing.h).
#ifndef PFDM_REPORT_SEGMENT_CURVES_H_
#define PFDM_REPORT_SEGMENT_CURVES_H_

#include <string>
#include <vector>

#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// The x of the report's curves: the time from the trigger (ms) where every
// frame has one, else the frame number; *timed says which.
std::vector<double> CycleX(const FitAnalysis& analysis, bool* timed);

// One chart per level (basal, mid, apical; the cap has no circumferential
// direction) of its segments' Ecc, named as the AHA names them, ED and ES
// marked; a table of each segment's peak Ecc and time to it; the index.
std::string SegmentCurvesHtml(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_SEGMENT_CURVES_H_
