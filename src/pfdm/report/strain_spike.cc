#include "pfdm/report/strain_spike.h"

#include <cmath>

namespace pfdm {

StrainSpike LargestStrainSpike(const std::vector<GlobalStrain>& frames) {
  StrainSpike spike;
  for (size_t t = 1; t + 1 < frames.size(); ++t) {
    for (bool longitudinal : {false, true}) {
      const auto field = longitudinal ? &GlobalStrain::level_ell_percent
                                      : &GlobalStrain::level_ecc_percent;
      for (int level = 0; level < 3; ++level) {
        const double departure =
            (frames[t].*field)[level] - 0.5 * ((frames[t - 1].*field)[level] +
                                               (frames[t + 1].*field)[level]);
        if (std::isnan(departure)) continue;
        if (spike.frame < 0 || std::abs(departure) > std::abs(spike.points)) {
          spike = {departure, static_cast<int>(t), level, longitudinal};
        }
      }
    }
  }
  return spike;
}

}  // namespace pfdm
