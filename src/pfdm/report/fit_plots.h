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
// rotation_measured (FitAnalysis::rotation_measured), when given: the twist
// panels leave out the frames where it is false, whose tau the fit held.
std::string ParameterPlotsSvg(const std::vector<Model>& frames,
                              const std::vector<bool>& rotation_measured = {});
SvgPlot ParameterPlots(const std::vector<Model>& frames,
                       const std::vector<bool>& rotation_measured = {});

// Over the frames: cavity volume (ED and ES marked), apex and base rotation
// with net twist, and radial and longitudinal contraction.  Rotations that
// are kNotMeasured are left out; where none is measured, so is their panel.
// volume_surface: what the volumes enclose (FitAnalysis::volume_surface);
// only the cavity's gives an ejection fraction, ED at ed_frame.  The x axis
// is the time from the trigger (ms) when every summary has one, else the
// frame number.
std::string CycleCurvesSvg(const std::vector<ClinicalSummary>& summaries,
                           const std::string& volume_surface = "cavity",
                           int ed_frame = 0);
SvgPlot CycleCurves(const std::vector<ClinicalSummary>& summaries,
                    const std::string& volume_surface = "cavity",
                    int ed_frame = 0);

}  // namespace pfdm

#endif  // PFDM_REPORT_FIT_PLOTS_H_
