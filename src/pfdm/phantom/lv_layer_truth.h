// The LV phantom's strain per layer (issue 32), measured on its own
// material points from its analytic motion, never from pfdm's model: per
// segment, Ecc and Ell at the endocardium (w = -1), the mid-wall and the
// epicardium (w = +1), each third of the wall's thickening and Err across
// the wall, defined as report/layer_strain.h defines the fit's.
//
// Material: cells of the mid-wall, equal steps of its ED height fraction h
// (the prolate shell 0 to 1, the cylinder its segment's heights) and of
// longitude (120 of 3 degrees), each the transmural line at its (nu, phi)
// (a mu coordinate line; the cylinder's: radial); a cell's weight is its
// mid-wall ED area.  Segments as lv_truth.h's (thirds of h, 6/6/4 sectors
// counted counter-clockwise about +z from the body's -x), and, as the
// fit's layout (report/wall_motion.h), the apex cap, h below
// apex_cap_fraction, as segment 17.
// Strains from central differences of the moved points along h, phi and w:
// the phantom's coordinates are orthogonal at ED (prolate spheroidal, or
// cylindrical), so e_c = X_phi / |X_phi| and e_l = X_h / |X_h|, and Ecc =
// (|x_phi|^2 / |X_phi|^2 - 1) / 2, Ell likewise.  A third's thickness is
// along the mid-wall's current normal at the cell, as lv_truth.h's wall
// thickness; Err across the wall is the Green-Lagrange strain of the chord
// from the cell's endocardial to its epicardial material point.
#ifndef PFDM_PHANTOM_LV_LAYER_TRUTH_H_
#define PFDM_PHANTOM_LV_LAYER_TRUTH_H_

#include <array>
#include <vector>

#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {

struct LvLayerValues {  // Percent.
  double ecc_percent = 0.0;
  double ell_percent = 0.0;
  double thickening_percent = 0.0;  // Of the layer's third of the wall.
};

struct LvSegmentLayers {
  int segment = 0;  // 1-16, 17 the apex cap.
  // Endocardium, mid-wall, epicardium; NaN in a segment without material
  // (the cylinder's apical and basal segments outside its heights).
  std::array<LvLayerValues, 3> layers;
  // Of the chord across the wall.
  double err_percent = 0.0;
};

// [frame][segment 1..17 - 1] of the phantom as made (its options and
// frames); apex_cap_fraction 0: 16 segments.
std::vector<std::vector<LvSegmentLayers>> MeasureLvLayerTruth(
    const LvPhantom& phantom, double apex_cap_fraction = 0.1);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_LAYER_TRUTH_H_
