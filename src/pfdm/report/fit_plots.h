// The parameter functions (the paper's Fig. 5), rendered by gnuplot as SVG
// text; the curves over the cycle are report/cycle_charts.h's.
#ifndef PFDM_REPORT_FIT_PLOTS_H_
#define PFDM_REPORT_FIT_PLOTS_H_

#include <string>
#include <vector>

#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/model/model.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/gnuplot.h"

namespace pfdm {

// The paper's Fig. 5 for every frame: a1, a2, a3 as ratios to frame 0, twist
// tau in degrees, bending b0 and b2 in mm, each against the knot index from
// apex to base, one line per frame coloured on a colour bar (dark early,
// light late), ED (frame 0) and es_frame (-1: none) thicker; hovering over
// a line shows its frame ("frame 4 (ES)").
// rotation_measured (FitAnalysis::rotation_measured), when given: the twist
// panels leave out the frames where it is false, whose tau the fit held.
// covariances (FrameFit::covariance per frame), when given and computed:
// each line in a band of its knots' 95 % intervals (the ratios' from the
// frame's a's alone, frame 0's taken as exact).
std::string ParameterPlotsSvg(
    const std::vector<Model>& frames,
    const std::vector<bool>& rotation_measured = {},
    const std::vector<FrameCovariance>& covariances = {}, int es_frame = -1);
SvgPlot ParameterPlots(const std::vector<Model>& frames,
                       const std::vector<bool>& rotation_measured = {},
                       const std::vector<FrameCovariance>& covariances = {},
                       int es_frame = -1);

}  // namespace pfdm

#endif  // PFDM_REPORT_FIT_PLOTS_H_
