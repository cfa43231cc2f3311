#include "pfdm/io/segments_json.h"

#include <cmath>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kAnatomicalDefinition =
    "the AHA 17-segment model (Cerqueira et al. 2002): thirds of frame 0's "
    "axis from the base rim to the apex (1-6 basal, 7-12 mid, 13-16 "
    "apical) less the apex cap (17); basal and mid sectors of 60 degrees "
    "from the anterior RV insertion, the border of anterior (1, 7) and "
    "anteroseptal (2, 8), on through the septum (anteroseptal, inferoseptal) "
    "to inferior, inferolateral and anterolateral; apical sectors of 90 "
    "degrees with the septal one (14) centred 60 degrees past the anterior "
    "insertion; the insertion's longitude v is that of the nearest "
    "material point of frame 0's model.";

constexpr const char* kPlainDefinition =
    "not anatomical: without an RV insertion the sectors start at the "
    "model's -x axis (v = -180 degrees), which the fit's start takes from "
    "the data, and run counter-clockwise seen from the base; the numbers "
    "then depend on the case, not the anatomy, and the segments are named "
    "by level and sector ('basal 1'), not by wall. Give --rv_insertion "
    "x,y,z[,x,y,z] (anterior, inferior) or guide points with RV_INSERT.";

double Degrees(double radians) { return radians * kDegreesPerRadian; }

json Number(double value) { return std::isnan(value) ? json() : json(value); }

json Insertion(const RegionLayout& layout) {
  const bool inferior = !std::isnan(layout.inferior_v);
  json arc = json();
  if (inferior) {
    const double turn =
        layout.direction * (layout.inferior_v - layout.anchor_v);
    arc = Degrees(turn - 2 * kPi * std::floor(turn / (2 * kPi)));
  }
  return {
      {"anterior_v_deg", Degrees(layout.anchor_v)},
      {"inferior_v_deg", inferior ? json(Degrees(layout.inferior_v)) : json()},
      {"septal_arc_deg", arc},
      {"anterior_points", layout.anterior_points},
      {"inferior_points", layout.inferior_points},
      {"direction", layout.direction < 0
                        ? "clockwise seen from the base (decreasing v)"
                        : "counter-clockwise seen from the base "
                          "(increasing v)"}};
}

}  // namespace

json SegmentsSection(const FitAnalysis& analysis) {
  const RegionLayout& layout = analysis.layout;
  json section = {{"anatomical", layout.anatomical},
                  {"anchor", layout.anchor},
                  {"definition", layout.anatomical ? kAnatomicalDefinition
                                                   : kPlainDefinition}};
  if (layout.anatomical) section["rv_insertion"] = Insertion(layout);
  if (analysis.regional_limit != RegionalLimit::kNone) {
    section["through_the_wall"] = RegionalLimitNote(analysis.regional_limit);
  }
  if (layout.apex_cap_fraction > 0) {
    section["apex_cap"] = {
        {"height_fraction", layout.apex_cap_fraction},
        {"measured", analysis.apex_cap_measured},
        {"reason", analysis.apex_cap_measured
                       ? "frame 0's data reach the apex"
                       : "n/a: frame 0's data do not reach the apex (model."
                         "apex_in_data); the cap would be extrapolated"}};
  }
  return section;
}

json DyssynchronySection(const FitAnalysis& analysis) {
  const Dyssynchrony& d = analysis.dyssynchrony;
  const auto value = [](double v) { return std::isnan(v) ? json() : json(v); };
  json times = json::array(), frames = json::array();
  for (const SegmentPeak& peak : d.peaks) {
    times.push_back(value(peak.time_to_peak));
    frames.push_back(peak.frame < 0 ? json() : json(peak.frame));
  }
  return {{"index", value(d.index)},
          {"unit", d.in_ms ? "ms" : "frames"},
          {"segments", d.segments},
          {"definition",
           "the standard deviation (n - 1) of the segments' time from ED to "
           "their most negative Ecc, over segments 1-16 with Ecc measured in "
           "every frame (the apex cap's circumferential direction turns "
           "about its pole)"},
          {"time_to_peak", times},
          {"peak_frame", frames}};
}

json RegionLayersJson(const FitAnalysis& analysis, size_t r) {
  if (analysis.region_layers.empty()) return json();
  json layers = json::object();
  for (int k = 0; k < kWallLayers; ++k) {
    json ecc = json::array(), ell = json::array(), thickening = json::array();
    for (const std::vector<RegionLayers>& frame : analysis.region_layers) {
      const LayerStrain& layer = frame[r].layers[k];
      ecc.push_back(Number(layer.ecc_percent));
      ell.push_back(Number(layer.ell_percent));
      thickening.push_back(Number(layer.thickening_percent));
    }
    layers[kLayerNames[k]] = {{"ecc_percent", ecc},
                              {"ell_percent", ell},
                              {"thickening_percent", thickening}};
  }
  return layers;
}

json RegionErrJson(const FitAnalysis& analysis, size_t r) {
  if (analysis.region_layers.empty()) return json();
  json err = json::array();
  for (const std::vector<RegionLayers>& frame : analysis.region_layers) {
    err.push_back(Number(frame[r].err_percent));
  }
  return err;
}

}  // namespace pfdm
