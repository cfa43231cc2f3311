// Which numbers' 95 % intervals were shown to hold what they promise: on
// 120 noise draws of the independent LV phantom their interval held the
// noise-free fit's number in 93-98 % of the draws
// (docs/uncertainty_calibration.md).  Every other number's interval is
// not calibrated: EDV's held it in 53 %, ESV's in 82 %, and the rest were
// not measured; read them as lower bounds.  fit.json says which
// (uncertainty_calibrated), the report stars the others.
#ifndef PFDM_REPORT_INTERVAL_CALIBRATION_H_
#define PFDM_REPORT_INTERVAL_CALIBRATION_H_

#include <string>
#include <vector>

namespace pfdm {

enum class Calibration { kCalibrated, kNotCalibrated };

// fit.json keys of the calibrated numbers: the ejection section's
// "ratio"; the frames' net twist, shortening, radial contraction, GCS and
// GLS (and the peaks); the segments' Ecc (and its peak), radial
// contraction and rotation.
const std::vector<std::string>& CalibratedIntervalKeys();

// What fit.json's uncertainty_calibrated says of the others.
extern const char* const kCalibrationNote;

}  // namespace pfdm

#endif  // PFDM_REPORT_INTERVAL_CALIBRATION_H_
