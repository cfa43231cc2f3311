#include "pfdm/io/not_measured_json.h"

#include <cstddef>

namespace pfdm {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kNotMeasuredDefinition =
    "null marks what the data cannot determine.  A turn about the long axis "
    "is seen only on tracked points (ids in more than one frame: tags); in "
    "the frames listed, which have none (contours), or when frame 0 has none, "
    "the fit holds tau, and every number a turn makes is null: the "
    "rotations, twists, torsion and shear angle in clinical (a solid's "
    "endo_* and epi_* ones too), gcl_percent, and the regions' rotation_deg "
    "and ecl_percent.";

constexpr const char* kExtrapolatedDefinition =
    "Frame 0's data do not reach the apex (model apex_in_data): the levels "
    "listed (thirds of frame 0's length, whose middle lies below the lowest "
    "data point; the apex cap, segment 17, always) and the apical ring (at "
    "20 % of the length, when below it) "
    "are the model's continuation of the data above them.  Unless shown "
    "(--extrapolated), their numbers are null: the levels' regions and "
    "strains, the apical ring's rotations, the net twists, torsion and "
    "shear angle.  Volumes and mass include the extrapolated apex cap "
    "(the frames' quality says so), and unless shown, they and the ejection "
    "fraction have no interval (--uncertainty on): their noise's would be "
    "about a cap the data never saw.";

constexpr const char* kShortSpanDefinition =
    "In the frames listed the data span under 75 % of frame 0's along the "
    "long axis (the verdict's short_span: contours that lost a slice): "
    "the ventricle beyond the data is not in them, and unless "
    "shown (--extrapolated) their volumes, mass and myocardial volume "
    "change are null, and so are the ejection fraction's esv_ml and ratio "
    "(end-systole may be such a frame).";

constexpr const char* kWallsUnseenDefinition =
    "In the frames listed a solid's tags lie near the wall's middle and "
    "no contour of either wall places the walls (the verdict's "
    "walls_unseen: mid-wall tags beside contours drawn in other frames): "
    "their volumes, mass, myocardial volume change, wall thickness and "
    "thickening, each wall's radial contraction and rotations, the "
    "regions' thickening and the layers' strains are null.  The mid-wall's "
    "motion is measured, and end-systole is the frame of least volume "
    "inside it (ejection_fraction.es_by_midwall): the ejection fraction's "
    "esv_ml and ratio are null when that frame is one of these.";

// The frames where `measured` is false, with the definition; null when
// there are none.
json FramesLeftOut(const std::vector<bool>& measured, const char* definition) {
  json frames = json::array();
  for (size_t t = 0; t < measured.size(); ++t) {
    if (!measured[t]) frames.push_back(t);
  }
  if (frames.empty()) return json();
  return {{"frames", frames}, {"definition", definition}};
}

// The levels and the apical ring measured where frame 0 has no data
// (FitAnalysis::level_extrapolated); null when there are none.
json Extrapolated(const FitAnalysis& analysis) {
  static const char* const kLevelNames[] = {"basal", "mid", "apical",
                                            "apex cap"};
  json levels = json::array();
  for (int level : {kBasal, kMid, kApical, kApex}) {
    if (analysis.level_extrapolated[level]) {
      levels.push_back(kLevelNames[level]);
    }
  }
  if (levels.empty() && !analysis.apex_ring_extrapolated) return json();
  return {{"levels", levels},
          {"apex_ring", analysis.apex_ring_extrapolated},
          {"shown", analysis.extrapolated_shown},
          {"definition", kExtrapolatedDefinition}};
}

}  // namespace

json NotMeasured(const FitAnalysis& analysis) {
  json frames = json::array();
  for (size_t t = 0; t < analysis.rotation_measured.size(); ++t) {
    if (!analysis.rotation_measured[t]) frames.push_back(t);
  }
  const json extrapolated = Extrapolated(analysis);
  const json short_span =
      FramesLeftOut(analysis.volume_measured, kShortSpanDefinition);
  const json walls_unseen =
      FramesLeftOut(analysis.walls_measured, kWallsUnseenDefinition);
  if (frames.empty() && extrapolated.is_null() && short_span.is_null() &&
      walls_unseen.is_null()) {
    return json();
  }
  json section;
  if (!frames.empty()) {
    section = {{"frames", frames}, {"definition", kNotMeasuredDefinition}};
  }
  if (!extrapolated.is_null()) section["extrapolated"] = extrapolated;
  if (!short_span.is_null()) section["short_span"] = short_span;
  if (!walls_unseen.is_null()) section["walls_unseen"] = walls_unseen;
  return section;
}

}  // namespace pfdm
