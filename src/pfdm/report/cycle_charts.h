// The report's curves over the cycle as inline SVG charts (svg_chart.h),
// each value shown on hover: volume and its rate of change, rotation and
// net twist, torsion, contraction, and global strain.
#ifndef PFDM_REPORT_CYCLE_CHARTS_H_
#define PFDM_REPORT_CYCLE_CHARTS_H_

#include <string>
#include <vector>

#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// dV/dt per frame by central differences (one-sided at the ends), in ml
// per unit of x (ml/s for x in seconds); empty for fewer than 2 frames.
std::vector<double> VolumeRate(const std::vector<double>& volume_ml,
                               const std::vector<double>& x);

// The peak ejection rate (the most negative dV/dt, as a positive number)
// and the peak filling rate (the most positive after ES), in the rate's
// unit; 0 where there is none.
struct VolumeRatePeaks {
  double ejection = 0.0;
  double filling = 0.0;
};
VolumeRatePeaks PeakVolumeRates(const std::vector<double>& rate, int es_frame);

// The section's charts, against the time from the trigger where known,
// else the frame; ED and ES marked.
std::string CycleChartsHtml(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_CYCLE_CHARTS_H_
