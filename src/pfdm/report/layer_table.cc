#include "pfdm/report/layer_table.h"

#include <sstream>

#include "pfdm/report/report_text.h"
#include "pfdm/util/markup_escape.h"

namespace pfdm {
namespace {

// Ecc, Ell and thickening, each over the three layers, then Err.
std::string Header() {
  std::ostringstream h;
  h << "<table><tr><th rowspan=\"2\">segment</th>"
       "<th rowspan=\"2\" class=\"l\">region</th>"
       "<th colspan=\"3\">Ecc %</th><th colspan=\"3\">Ell %</th>"
       "<th colspan=\"3\">thickening of the third %</th>"
       "<th rowspan=\"2\">Err across the wall %</th></tr>\n<tr>";
  for (int quantity = 0; quantity < 3; ++quantity) {
    h << "<th>endo</th><th>mid</th><th>epi</th>";
  }
  h << "</tr>\n";
  return h.str();
}

std::string Row(const WallRegion& region, const RegionLayers& layers) {
  std::ostringstream h;
  h << "<tr><td>" << region.segment << "</td><td class=\"l\">"
    << EscapeMarkup(region.Name()) << "</td>";
  for (const LayerStrain& layer : layers.layers) {
    h << "<td" << Tint(-layer.ecc_percent, 30.0) << ">"
      << Fixed(layer.ecc_percent, 1) << "</td>";
  }
  for (const LayerStrain& layer : layers.layers) {
    h << "<td" << Tint(-layer.ell_percent, 30.0) << ">"
      << Fixed(layer.ell_percent, 1) << "</td>";
  }
  for (const LayerStrain& layer : layers.layers) {
    h << "<td" << Tint(layer.thickening_percent, 60.0) << ">"
      << Fixed(layer.thickening_percent, 1) << "</td>";
  }
  h << "<td" << Tint(layers.err_percent, 60.0) << ">"
    << Fixed(layers.err_percent, 1) << "</td></tr>\n";
  return h.str();
}

}  // namespace

std::string LayerTableHtml(const FitAnalysis& analysis) {
  if (analysis.region_layers.empty()) return "";
  const size_t es = analysis.ejection_fraction.es_frame;
  std::ostringstream h;
  h << "<h2>Strain per layer at ES (frame " << es << ")</h2>\n" << Header();
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    h << Row(analysis.regions[r], analysis.region_layers[es][r]);
  }
  h << "</table>\n<p class=\"note\">Against the ED frame, on the solid's "
       "material points. Ecc, Ell: the Green-Lagrange strains of the "
       "endocardium, the mid-wall and the epicardium in their own tangent "
       "planes. Thickening: of the wall's inner, middle and outer third "
       "along the mid-wall's normal. Err: the Green-Lagrange strain of the "
       "chord across the wall from endocardium to epicardium. On the LV "
       "phantom's tags through the wall (docs/report.md) Ecc and Ell come "
       "within about 3.5 points of the truth, Err within 10, and a third's "
       "thickening only within 17: the fitted profile across the wall is "
       "coarser than the segments. Without tracked points (contours) the "
       "thirds are n/a: nothing places a layer inside the wall.</p>\n";
  return h.str();
}

}  // namespace pfdm
