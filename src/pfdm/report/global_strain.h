// Global circumferential and longitudinal strain (GCS, GLS) and their
// per-level means, from the regional strains of wall_motion.h.
#ifndef PFDM_REPORT_GLOBAL_STRAIN_H_
#define PFDM_REPORT_GLOBAL_STRAIN_H_

#include <array>
#include <vector>

#include "pfdm/report/wall_motion.h"

namespace pfdm {

// One frame's strains, percent, Green-Lagrange against frame 0.  GCS and
// GLS are the area-weighted means of Ecc and Ell over the whole sampled
// surface, from the apex pole (never sampled itself) to the base rim: the
// segments' means weighted by their frame-0 areas.  The levels likewise
// over their segments (kBasal, kMid, kApical; the apex cap, segment 17,
// counts into the apical level, which is then the whole apical third).
struct GlobalStrain {
  double gcs_percent = 0.0;
  double gls_percent = 0.0;
  double gcl_percent = 0.0;  // Mean shear Ecl.
  std::array<double, 3> level_ecc_percent{};
  std::array<double, 3> level_ell_percent{};
};

GlobalStrain SummarizeStrain(const std::vector<WallRegion>& regions,
                             const std::vector<RegionMotion>& motion);

// The most negative value of a per-frame series and its frame (0, 0 for an
// empty one): peak systolic shortening.
struct StrainPeak {
  double percent = 0.0;
  int frame = 0;
};
StrainPeak PeakGcs(const std::vector<GlobalStrain>& frames);
StrainPeak PeakGls(const std::vector<GlobalStrain>& frames);

// Per region, the most negative Ecc over the frames ([frame][region]).
std::vector<double> PeakRegionEcc(
    const std::vector<std::vector<RegionMotion>>& motion);

}  // namespace pfdm

#endif  // PFDM_REPORT_GLOBAL_STRAIN_H_
