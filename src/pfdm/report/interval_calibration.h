// Which numbers' 95 % intervals were shown to hold what they promise, by
// the kind of data fitted.  Over 100 noise draws of the independent LV
// phantom (300 for tags; docs/uncertainty_calibration.md) an interval is
// calibrated where it held the noise-free fit's number in 90-98 % of draws
// (issue 30's rule; to the whole percent, with and without the hypokinetic
// segment where both were run); every other interval is not (fit.json's
// uncertainty_calibrated says which, the report stars the others): too
// narrow or too wide.  Data of another kind (tags and contours mixed,
// tags some frames lose) have no calibrated interval.
#ifndef PFDM_REPORT_INTERVAL_CALIBRATION_H_
#define PFDM_REPORT_INTERVAL_CALIBRATION_H_

#include <string>
#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"

namespace pfdm {

enum class Calibration { kCalibrated, kNotCalibrated };

// The kinds of data calibrated: tags on one surface (a mid-wall fit), tags
// through the wall (a solid), both walls' contours (no frame tracked, a
// solid), the endocardium's contours alone (no frame tracked, one
// surface: the endocardium), the epicardium's alone (likewise), contours
// of neither wall (no frame tracked, one surface: the mid-wall); kOther:
// none.
enum class IntervalData {
  kMidwallTags,
  kWallTags,
  kContours,
  kEndoContours,
  kEpiContours,
  kMidwallContours,
  kOther
};

// The fit's kind: tags where every frame is tracked, by whether the model
// is a solid; where none is (FrameFit::tracked), wall contours if the
// model is a solid, else by the wall of its one surface: endocardial,
// epicardial or mid-wall contours; else, and wherever a tracked frame has
// contours beside its tags (FrameFit::mixed), kOther (a mix).
IntervalData IntervalDataOf(const SequenceFit& fit);

// "midwall tags", "wall tags", "wall contours", "endocardial contours",
// "epicardial contours", "midwall contours" or "other".
std::string IntervalDataName(IntervalData data);

// fit.json keys of data's calibrated numbers: a key holds wherever it
// names a number (the frames', the peaks', the segments'), as
// "radial_contraction_percent" the frames' and the segments'.
const std::vector<std::string>& CalibratedIntervalKeys(IntervalData data);

// Whether `key`'s intervals are calibrated on data.
Calibration KeyCalibration(IntervalData data, const std::string& key);

// What fit.json's uncertainty_calibrated says of data's intervals.
std::string CalibrationNote(IntervalData data);

}  // namespace pfdm

#endif  // PFDM_REPORT_INTERVAL_CALIBRATION_H_
