// The report's table of a solid's strain per layer at ES (layer_strain.h):
// each segment's Ecc, Ell and thickening at the endocardium, mid-wall and
// epicardium, and its Err across the wall.
#ifndef PFDM_REPORT_LAYER_TABLE_H_
#define PFDM_REPORT_LAYER_TABLE_H_

#include <string>

#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// An <h2>, the table and a note; "" without a wall (no region_layers).
std::string LayerTableHtml(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_LAYER_TABLE_H_
