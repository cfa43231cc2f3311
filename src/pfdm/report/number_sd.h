// How sure a fit's derived numbers are: their standard deviations, held in
// the same structs as the numbers themselves so that each has its sd at
// the same place (report/number_uncertainty.h computes them).
#ifndef PFDM_REPORT_NUMBER_SD_H_
#define PFDM_REPORT_NUMBER_SD_H_

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

// The normal distribution's two-sided 95 % quantile.
inline constexpr double kZ95 = 1.959963984540054;

// Every field a standard deviation of the FitAnalysis number of the same
// name, frame and segment; NaN where the number is kNotMeasured or has no
// sd (frame, time_ms, area_mm2, the per-knot ratios: their parameters' sd
// is parameters.csv's).  ejection_fraction's edv_ml, esv_ml and ratio are
// sds; its frames are the analysis's.
struct NumberSd {
  bool computed = false;  // Every frame had its covariance.
  std::vector<ClinicalSummary> clinical;
  std::vector<std::vector<RegionMotion>> region_motion;  // [frame][region]
  std::vector<GlobalStrain> strain;
  EjectionFraction ejection_fraction;
};

// kZ95 sd: the 95 % interval is value +- this; NaN for a NaN sd.
inline double HalfWidth95(double sd) { return kZ95 * sd; }

// The 95 % interval {low, high} of `value`: HalfWidth95(sd) about value
// minus its noise bias (report/local_field_noise.h; NaN: none).
inline std::array<double, 2> Interval95(double value, double sd, double bias) {
  const double centre = value - (std::isnan(bias) ? 0.0 : bias);
  return {centre - HalfWidth95(sd), centre + HalfWidth95(sd)};
}

// The scalar fields that carry a number (and so an sd), in a fixed order:
// what the delta method varies and NumberSd fills.
std::vector<double*> ClinicalFields(ClinicalSummary* summary);
std::vector<double*> RegionFields(RegionMotion* motion);
std::vector<double*> StrainFields(GlobalStrain* strain);
// Their names, in the same order: fit.json's keys (the volume's is
// "volume_ml" here, "<surface>_volume_ml" in fit.json's frames).
const std::vector<std::string>& ClinicalFieldNames();
const std::vector<std::string>& RegionFieldNames();
const std::vector<std::string>& StrainFieldNames();

}  // namespace pfdm

#endif  // PFDM_REPORT_NUMBER_SD_H_
