// The AHA-style polar map ("bull's-eye") of regional numbers and the
// strain curves over the cycle, rendered by gnuplot as SVG text.
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
};

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

// The report's three maps: peak Ecc over the frames, and radial
// contraction and rotation at end-systole; no rotation map where it is not
// measured (FitAnalysis::rotation_measured).
std::vector<BullseyeMap> ClinicalBullseyeMaps(const FitAnalysis& analysis);

// Over the frames: Ecc and Ell, the global means (GCS, GLS) and each
// level's, one panel each.
std::string StrainCurvesSvg(const std::vector<GlobalStrain>& strain);
SvgPlot StrainCurves(const std::vector<GlobalStrain>& strain);

}  // namespace pfdm

#endif  // PFDM_REPORT_BULLSEYE_PLOT_H_
