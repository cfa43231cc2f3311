#include "pfdm/report/global_strain.h"

#include <algorithm>

namespace pfdm {
namespace {

StrainPeak PeakOf(const std::vector<GlobalStrain>& frames,
                  double GlobalStrain::*field) {
  StrainPeak peak;
  for (size_t t = 0; t < frames.size(); ++t) {
    if (t == 0 || frames[t].*field < peak.percent) {
      peak = {frames[t].*field, static_cast<int>(t)};
    }
  }
  return peak;
}

}  // namespace

GlobalStrain SummarizeStrain(const std::vector<WallRegion>& regions,
                             const std::vector<RegionMotion>& motion) {
  GlobalStrain strain;
  double area = 0.0;
  std::array<double, 3> level_area{};
  for (size_t r = 0; r < regions.size() && r < motion.size(); ++r) {
    const RegionMotion& m = motion[r];
    // The apex cap is part of the apical third.
    const int level = std::min<int>(regions[r].level, kApical);
    strain.gcs_percent += m.area_mm2 * m.ecc_percent;
    strain.gls_percent += m.area_mm2 * m.ell_percent;
    strain.gcl_percent += m.area_mm2 * m.ecl_percent;
    strain.level_ecc_percent[level] += m.area_mm2 * m.ecc_percent;
    strain.level_ell_percent[level] += m.area_mm2 * m.ell_percent;
    area += m.area_mm2;
    level_area[level] += m.area_mm2;
  }
  if (area > 0) {
    strain.gcs_percent /= area;
    strain.gls_percent /= area;
    strain.gcl_percent /= area;
  }
  for (int level = 0; level < 3; ++level) {
    if (level_area[level] == 0) continue;
    strain.level_ecc_percent[level] /= level_area[level];
    strain.level_ell_percent[level] /= level_area[level];
  }
  return strain;
}

StrainPeak PeakGcs(const std::vector<GlobalStrain>& frames) {
  return PeakOf(frames, &GlobalStrain::gcs_percent);
}

StrainPeak PeakGls(const std::vector<GlobalStrain>& frames) {
  return PeakOf(frames, &GlobalStrain::gls_percent);
}

std::vector<double> PeakRegionEcc(
    const std::vector<std::vector<RegionMotion>>& motion) {
  std::vector<double> peak;
  for (size_t t = 0; t < motion.size(); ++t) {
    peak.resize(std::max(peak.size(), motion[t].size()), 0.0);
    for (size_t r = 0; r < motion[t].size(); ++r) {
      if (t == 0 || motion[t][r].ecc_percent < peak[r]) {
        peak[r] = motion[t][r].ecc_percent;
      }
    }
  }
  return peak;
}

}  // namespace pfdm
