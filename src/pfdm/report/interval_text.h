// The report's text for a number's 95 % interval: value +- half-width.
#ifndef PFDM_REPORT_INTERVAL_TEXT_H_
#define PFDM_REPORT_INTERVAL_TEXT_H_

#include <string>

#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/interval_calibration.h"

namespace pfdm {

// " &plusmn; 1.2", the 95 % half-width (HalfWidth95) of a number whose sd
// is `sd`, with `digits` decimals, starred where the interval is not
// calibrated (interval_calibration.h); "" for a NaN sd (no covariance, or
// a number not measured).  With a `bias` (local_field_noise.h) over a
// tenth of the half-width, a "b" whose title says where the interval is
// centred (value - bias).
std::string PlusMinus(double sd, int digits,
                      Calibration calibration = Calibration::kCalibrated,
                      double bias = kNotMeasured);

// The sd of frame t's clinical number `field`, of its strain's, and of
// segment r's; NaN when analysis.sd was not computed.
double ClinicalSd(const FitAnalysis& analysis, size_t t,
                  double ClinicalSummary::*field);
double StrainSd(const FitAnalysis& analysis, size_t t,
                double GlobalStrain::*field);
double RegionSd(const FitAnalysis& analysis, size_t t, size_t r,
                double RegionMotion::*field);
// Their biases (analysis.noise_bias); NaN when it was not computed.
double ClinicalBias(const FitAnalysis& analysis, size_t t,
                    double ClinicalSummary::*field);
double StrainBias(const FitAnalysis& analysis, size_t t,
                  double GlobalStrain::*field);
double RegionBias(const FitAnalysis& analysis, size_t t, size_t r,
                  double RegionMotion::*field);

// What "+-" means in the report and the bull's-eye's "?" rule; "" when
// analysis.sd was not computed.
std::string IntervalNoteHtml(const FitAnalysis& analysis);

// The frame of segment r's peak (most negative) Ecc, as PeakRegionEcc.
int PeakEccFrame(const FitAnalysis& analysis, size_t r);

}  // namespace pfdm

#endif  // PFDM_REPORT_INTERVAL_TEXT_H_
