#include "pfdm/report/interval_text.h"

#include <cmath>
#include <cstdio>

namespace pfdm {

std::string PlusMinus(double sd, int digits, Calibration calibration,
                      double bias) {
  if (!Measured(sd)) return "";
  char text[160];
  std::snprintf(text, sizeof(text), " &plusmn; %.*f", digits, HalfWidth95(sd));
  std::string out = text;
  if (Measured(bias) && std::abs(bias) > 0.1 * HalfWidth95(sd)) {
    std::snprintf(text, sizeof(text),
                  "<sup title=\"95 %% interval about the value %s %.*f: the "
                  "bias the noise puts into it\">b</sup>",
                  bias > 0 ? "-" : "+", digits + 1, std::abs(bias));
    out += text;
  }
  if (calibration == Calibration::kCalibrated) return out;
  return out +
         "<sup title=\"not calibrated on this kind of data "
         "(docs/uncertainty_calibration.md)\">*</sup>";
}

namespace {

double ClinicalOf(const NumberSd& numbers, size_t t,
                  double ClinicalSummary::*field) {
  return numbers.computed && t < numbers.clinical.size()
             ? numbers.clinical[t].*field
             : kNotMeasured;
}

double StrainOf(const NumberSd& numbers, size_t t,
                double GlobalStrain::*field) {
  return numbers.computed && t < numbers.strain.size()
             ? numbers.strain[t].*field
             : kNotMeasured;
}

double RegionOf(const NumberSd& numbers, size_t t, size_t r,
                double RegionMotion::*field) {
  if (!numbers.computed || t >= numbers.region_motion.size() ||
      r >= numbers.region_motion[t].size()) {
    return kNotMeasured;
  }
  return numbers.region_motion[t][r].*field;
}

}  // namespace

double ClinicalSd(const FitAnalysis& analysis, size_t t,
                  double ClinicalSummary::*field) {
  return ClinicalOf(analysis.sd, t, field);
}

double StrainSd(const FitAnalysis& analysis, size_t t,
                double GlobalStrain::*field) {
  return StrainOf(analysis.sd, t, field);
}

double RegionSd(const FitAnalysis& analysis, size_t t, size_t r,
                double RegionMotion::*field) {
  return RegionOf(analysis.sd, t, r, field);
}

double ClinicalBias(const FitAnalysis& analysis, size_t t,
                    double ClinicalSummary::*field) {
  return ClinicalOf(analysis.noise_bias, t, field);
}

double StrainBias(const FitAnalysis& analysis, size_t t,
                  double GlobalStrain::*field) {
  return StrainOf(analysis.noise_bias, t, field);
}

double RegionBias(const FitAnalysis& analysis, size_t t, size_t r,
                  double RegionMotion::*field) {
  return RegionOf(analysis.noise_bias, t, r, field);
}

std::string IntervalNoteHtml(const FitAnalysis& analysis) {
  if (!analysis.sd.computed) return "";
  return "<p class=\"note\"><b>&plusmn;</b>: the half-width of the number's "
         "95 % interval from the fit's noise (--uncertainty on): 1.96 "
         "standard deviations by the delta method over each frame's "
         "parameter covariance, ED's and the frame's added, with the spread "
         "the local field's noise and frame 0's length (set by its highest "
         "noisy points) add; error bars on the curves and bands "
         "on the parameter functions likewise. <b>b</b>: the interval is "
         "centred not on the value but on the value minus the bias the "
         "noise puts into it (strain reads less contracted when the local "
         "field fits noise; the highest of many noisy points lies too "
         "high); its tooltip gives the shift. It "
         "covers the noise of the data, not a bias of the model or of the "
         "points' correspondences. On the bull's-eyes a value marked "
         "<b>?</b> is uncertain: its half-width exceeds a quarter of the "
         "normal size of the number at ES (peak Ecc 4.5 %, radial "
         "contraction 5.5 %, rotation 2&deg;), too wide to tell a normal "
         "segment from a hypokinetic one; unmarked values are reliable by "
         "that rule (docs/uncertainty.md). <b>*</b>: an interval not "
         "calibrated on this kind of data. " +
         CalibrationNote(analysis.interval_data) + "</p>\n";
}

int PeakEccFrame(const FitAnalysis& analysis, size_t r) {
  int frame = 0;
  double least = 0.0;
  for (size_t t = 0; t < analysis.region_motion.size(); ++t) {
    const double ecc = analysis.region_motion[t][r].ecc_percent;
    if (Measured(ecc) && ecc < least) {
      least = ecc;
      frame = static_cast<int>(t);
    }
  }
  return frame;
}

}  // namespace pfdm
