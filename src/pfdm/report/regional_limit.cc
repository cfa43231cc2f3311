#include "pfdm/report/regional_limit.h"

#include <algorithm>

namespace pfdm {

RegionalLimit RegionalLimitOf(const SequenceFit& fit) {
  if (!fit.config.Solid() || fit.frames.empty()) return RegionalLimit::kNone;
  if (fit.frames.back().state.local.transmural()) return RegionalLimit::kThirds;
  const auto tracked = [](const FrameFit& f) { return f.tracked; };
  // Held or measured (the contours place the walls), the depths are no ring's.
  const auto held = [](const FrameFit& f) {
    return f.depths_held || f.depths_measured;
  };
  const bool ranked =
      std::any_of(fit.frames.begin(), fit.frames.end(), tracked) &&
      std::none_of(fit.frames.begin(), fit.frames.end(), held);
  return ranked ? RegionalLimit::kRing : RegionalLimit::kThickening;
}

std::string RegionalLimitNote(RegionalLimit limit) {
  switch (limit) {
    case RegionalLimit::kRing:
      return "A regional defect through the wall does not show here: the "
             "tags' depths were ranked within their ring and the local field, "
             "if any, moves every layer alike (--local_transmural off), so a "
             "segment that moves unlike its ring reads as its ring, its "
             "thickening too. Fit with --tag_depths held, or with "
             "--local_transmural on, to look for one.";
    case RegionalLimit::kThickening:
      return "A segment's thickening here is its ring's: the local field, "
             "if any, moves every layer alike (--local_transmural off), so a "
             "segment that thickens unlike its ring does not show in it, "
             "though its motion does. With --local_transmural on each wall "
             "has its own field.";
    case RegionalLimit::kThirds:
      return "The thickening of each third of the wall here is the local "
             "field's bend between the walls (--local_transmural on), which "
             "only tags inside the wall set and their depths and noise move: "
             "on the project's phantoms the thirds read 20-47 points off "
             "their truth. The whole wall's thickening, between the walls, "
             "does not depend on it.";
    case RegionalLimit::kNone:
      break;
  }
  return "";
}

}  // namespace pfdm
