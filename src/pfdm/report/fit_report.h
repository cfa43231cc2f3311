// report.html: one self-contained page a clinician reads a fit from.
#ifndef PFDM_REPORT_FIT_REPORT_H_
#define PFDM_REPORT_FIT_REPORT_H_

#include <string>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// The key numbers (EF, twist and contraction at end-systole), the 3D view
// of the fitted surfaces and data (report/surface_view.h), the parameter
// functions (gnuplot's SVG document, inlined), the curves over the cycle
// (report/cycle_charts.h), the per-frame error and clinical table, the
// regional wall motion at end-systole with the bull's-eye maps where given
// (report/bullseye_plot.h), the segments' strain curves and dyssynchrony
// (report/segment_curves.h), and a segmentation's slices with the fitted
// walls' cuts where given (io/segmentation_overlay.h).  No external
// resources: the 3D view's script is inlined (report/viewer_script.h).
std::string FitReportHtml(const PointSequence& points, const SequenceFit& fit,
                          const FitAnalysis& analysis,
                          const std::string& parameters_svg,
                          const std::string& bullseye_svg = "",
                          const std::string& slices_svg = "");

// An SVG document's <svg> element, without the XML prolog and doctype that
// may not stand inside HTML.
std::string InlineSvg(const std::string& svg_document);

}  // namespace pfdm

#endif  // PFDM_REPORT_FIT_REPORT_H_
