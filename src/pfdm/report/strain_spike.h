// A strain curve's jitter from frame to frame, which the curve shows as a
// measurement (issue 31: biv-me's basal Ell read -11, +6, -7 % over three
// frames).
#ifndef PFDM_REPORT_STRAIN_SPIKE_H_
#define PFDM_REPORT_STRAIN_SPIKE_H_

#include <vector>

#include "pfdm/report/global_strain.h"

namespace pfdm {

// The largest departure of a level's Ecc or Ell at a frame from the mean
// of its two neighbouring frames, in points, and where.  The first and
// last frames have one neighbour and are not judged; levels not measured
// (NaN) are left out.
struct StrainSpike {
  double points = 0.0;        // Signed: above (+) or below its neighbours.
  int frame = -1;             // -1: fewer than 3 frames.
  int level = 0;              // kBasal, kMid, kApical.
  bool longitudinal = false;  // Ell, else Ecc.
};
StrainSpike LargestStrainSpike(const std::vector<GlobalStrain>& frames);

}  // namespace pfdm

#endif  // PFDM_REPORT_STRAIN_SPIKE_H_
