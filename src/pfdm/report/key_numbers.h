// The report's key numbers: a card each for the ejection fraction (or the
// volumes), a solid's mass and thickening, twist, torsion, contraction,
// shortening and peak global strains, at end-systole, each with its 95 %
// interval where computed (starred where not calibrated).
#ifndef PFDM_REPORT_KEY_NUMBERS_H_
#define PFDM_REPORT_KEY_NUMBERS_H_

#include <string>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {

std::string KeyNumbersHtml(const SequenceFit& fit, const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_KEY_NUMBERS_H_
