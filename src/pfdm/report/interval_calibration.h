// Which numbers' 95 % intervals were shown to hold what they promise: on
// noise draws of the independent LV phantom their interval held the
// noise-free fit's number in 83-96 % of the draws
// (docs/uncertainty_calibration.md).  Every other number's interval is
// not calibrated: EDV's was too narrow by about 4, GCS's, GLS's and the
// segments' are the noise's spread about a biased value, and the rest
// were not measured; read them as lower bounds.  fit.json says which
// (uncertainty_calibrated), the report stars the others.
#ifndef PFDM_REPORT_INTERVAL_CALIBRATION_H_
#define PFDM_REPORT_INTERVAL_CALIBRATION_H_

#include <string>
#include <vector>

namespace pfdm {

enum class Calibration { kCalibrated, kNotCalibrated };

// fit.json keys of the calibrated numbers: the ejection section's "ratio"
// and "esv_ml", and the frames' "net_twist_deg",
// "longitudinal_shortening_percent" and "radial_contraction_percent".
const std::vector<std::string>& CalibratedIntervalKeys();

// What fit.json's uncertainty_calibrated says of the others.
extern const char* const kCalibrationNote;

}  // namespace pfdm

#endif  // PFDM_REPORT_INTERVAL_CALIBRATION_H_
