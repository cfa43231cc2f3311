// The AHA-style polar map ("bull's-eye") of regional numbers, rendered by
// gnuplot as SVG text.
#ifndef PFDM_REPORT_BULLSEYE_PLOT_H_
#define PFDM_REPORT_BULLSEYE_PLOT_H_

#include <string>
#include <utility>
#include <vector>

#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

// Colour scales, each symmetric about 0 (white).
enum class BullseyePalette {
  kShorteningRed,   // Negative red: strain, where shortening is negative.
  kContractionRed,  // Positive red: contraction, positive inward.
  kPurpleGreen,     // No better or worse side: rotation.
};

struct BullseyeMap {
  std::string title;           // Panel title, units included.
  std::vector<double> values;  // One per region of the layout.
  BullseyePalette palette = BullseyePalette::kShorteningRed;
  // The values' 95 % half-widths (empty: none, --uncertainty off); a
  // segment whose half-width exceeds uncertain_half_width is marked
  // uncertain ("?" after its value), a reliable one is not.
  std::vector<double> half_widths{};
  double uncertain_half_width = 0.0;
};

// The bull's-eye's rule: a segment is uncertain when its 95 % interval's
// half-width exceeds a quarter of the number's normal size at end-systole
// (peak Ecc about -18 %, radial contraction about 22 %, apical rotation
// about 8 degrees): an interval that wide could hold both a normal and a
// hypokinetic segment.
inline constexpr double kUncertainEccPercent = 4.5;
inline constexpr double kUncertainContractionPercent = 5.5;
inline constexpr double kUncertainRotationDeg = 2.0;

// Whether map's segment r is marked uncertain.
bool UncertainSegment(const BullseyeMap& map, size_t r);

// The display angles (degrees, counter-clockwise from the +x of the page)
// a region spans: as the AHA draws it, sector 1 of every ring centred at
// the top and sectors numbered counter-clockwise on the page; the apex cap
// (segment 17) the whole disc in the centre.  Anatomical segments
// (RegionLayout::anatomical) run clockwise about the long axis seen from the
// base, so the map is the LV seen from its apex, the standard view: anterior
// at the top, the septum (2, 3, 8, 9, 14) on the left, lateral on the
// right.  Otherwise sectors run counter-clockwise seen from the base and
// the map is the LV seen from its base, not anchored to the anatomy.
std::pair<double, double> BullseyeSpanDeg(const WallRegion& region);

// Rings from the centre: the apex cap (segment 17, when the layout has it),
// apical, mid, basal; each segment filled by its value on the panel's scale
// (white and "n/a" where not measured) and labelled with its number and
// value.  One panel per map, side by side.
std::string BullseyeSvg(const std::vector<WallRegion>& regions,
                        const std::vector<BullseyeMap>& maps);
SvgPlot Bullseye(const std::vector<WallRegion>& regions,
                 const std::vector<BullseyeMap>& maps);

// The report's maps: peak Ecc and peak Ell over the frames, radial
// contraction at end-systole, a solid's wall thickening and rotation at
// end-systole; no thickening map for one surface, no rotation map where
// it is not measured (FitAnalysis::rotation_measured).
std::vector<BullseyeMap> ClinicalBullseyeMaps(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_BULLSEYE_PLOT_H_
