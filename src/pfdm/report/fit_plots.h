// The plots a physician reads a fit from, rendered by gnuplot as SVG text.
#ifndef PFDM_REPORT_FIT_PLOTS_H_
#define PFDM_REPORT_FIT_PLOTS_H_

#include <string>
#include <vector>

#include "pfdm/model/model.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/gnuplot.h"

namespace pfdm {

// The paper's Fig. 5 for every frame: a1, a2, a3 as ratios to frame 0, twist
// tau in degrees, bending b0 and b2 in mm, each against the knot index from
// apex to base, one line per frame (dark early, light late) with a legend.
std::string ParameterPlotsSvg(const std::vector<Model>& frames);
SvgPlot ParameterPlots(const std::vector<Model>& frames);

// Over the frames: cavity volume (ED and ES marked), apex and base rotation
// with net twist, and radial and longitudinal contraction.
// volume_surface: what the volumes enclose (FitAnalysis::volume_surface);
// only the cavity's gives an ejection fraction.
std::string CycleCurvesSvg(const std::vector<ClinicalSummary>& summaries,
                           const std::string& volume_surface = "cavity");
SvgPlot CycleCurves(const std::vector<ClinicalSummary>& summaries,
                    const std::string& volume_surface = "cavity");

}  // namespace pfdm

#endif  // PFDM_REPORT_FIT_PLOTS_H_
