// The report's verdict box: the fit's quality in one look, green, amber or
// red, with every frame's reasons where it is not ok.
#ifndef PFDM_REPORT_VERDICT_BOX_H_
#define PFDM_REPORT_VERDICT_BOX_H_

#include <string>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// An HTML <div> (with its own inline style), escaped.
std::string VerdictBoxHtml(const SequenceFit& fit, const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_VERDICT_BOX_H_
