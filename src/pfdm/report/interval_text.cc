#include "pfdm/report/interval_text.h"

#include <cstdio>

namespace pfdm {

std::string PlusMinus(double sd, int digits, Calibration calibration) {
  if (!Measured(sd)) return "";
  char text[64];
  std::snprintf(text, sizeof(text), " &plusmn; %.*f", digits, HalfWidth95(sd));
  if (calibration == Calibration::kCalibrated) return text;
  return std::string(text) +
         "<sup title=\"not calibrated: read as a lower bound\">*</sup>";
}

double ClinicalSd(const FitAnalysis& analysis, size_t t,
                  double ClinicalSummary::*field) {
  const NumberSd& sd = analysis.sd;
  return sd.computed && t < sd.clinical.size() ? sd.clinical[t].*field
                                               : kNotMeasured;
}

double StrainSd(const FitAnalysis& analysis, size_t t,
                double GlobalStrain::*field) {
  const NumberSd& sd = analysis.sd;
  return sd.computed && t < sd.strain.size() ? sd.strain[t].*field
                                             : kNotMeasured;
}

double RegionSd(const FitAnalysis& analysis, size_t t, size_t r,
                double RegionMotion::*field) {
  const NumberSd& sd = analysis.sd;
  if (!sd.computed || t >= sd.region_motion.size() ||
      r >= sd.region_motion[t].size()) {
    return kNotMeasured;
  }
  return sd.region_motion[t][r].*field;
}

std::string IntervalNoteHtml(const FitAnalysis& analysis) {
  if (!analysis.sd.computed) return "";
  return "<p class=\"note\"><b>&plusmn;</b>: the half-width of the number's "
         "95 % interval from the fit's noise (--uncertainty on): 1.96 "
         "standard deviations by the delta method over each frame's "
         "parameter covariance, ED's and the frame's added; error bars on "
         "the curves and bands on the parameter functions likewise. It "
         "covers the noise of the data, not a bias of the model or of "
         "the points' correspondences. On the bull's-eyes a value marked "
         "<b>?</b> is uncertain: its half-width exceeds a quarter of the "
         "normal size of the number at ES (peak Ecc 4.5 %, radial "
         "contraction 5.5 %, rotation 2&deg;), too wide to tell a normal "
         "segment from a hypokinetic one; unmarked values are reliable by "
         "that rule (docs/uncertainty.md). <b>*</b>: an interval not "
         "calibrated, to be read as a lower bound: on noise draws of the "
         "LV phantom only the ejection (volume) fraction's, ESV's, net "
         "twist's, radial contraction's and shortening's held the "
         "noise-free number in 83-96 % of draws; EDV's was too narrow, "
         "GCS's, GLS's and the segments' sat about a biased value, and the "
         "bull's-eye's rule errs toward calling a segment reliable "
         "(docs/uncertainty_calibration.md).</p>\n";
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
