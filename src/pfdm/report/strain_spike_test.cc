#include "pfdm/report/strain_spike.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Basal Ell -11, +6, -7 % over three frames (issue 31's biv-me frames
// 12-14) departs from its neighbours' mean by 15 points at the middle one;
// a linear curve by none, and a level not measured is left out.
TEST(StrainSpikeTest, LargestDepartureFromTheNeighboursMean) {
  std::vector<GlobalStrain> frames(5);
  const double ell[] = {0.0, -11.0, 6.0, -7.0, -8.0};
  for (int t = 0; t < 5; ++t) {
    frames[t].level_ell_percent[kBasal] = ell[t];
    frames[t].level_ecc_percent[kMid] = -2.0 * t;
    frames[t].level_ecc_percent[kApical] = std::nan("");
  }
  const StrainSpike spike = LargestStrainSpike(frames);
  EXPECT_DOUBLE_EQ(spike.points, 15.0);
  EXPECT_EQ(spike.frame, 2);
  EXPECT_EQ(spike.level, kBasal);
  EXPECT_TRUE(spike.longitudinal);
  for (int t = 0; t < 5; ++t) frames[t].level_ell_percent[kBasal] = 0.0;
  const StrainSpike none = LargestStrainSpike(frames);
  EXPECT_DOUBLE_EQ(none.points, 0.0);
  EXPECT_EQ(LargestStrainSpike({frames[0], frames[1]}).frame, -1);
}

}  // namespace
}  // namespace pfdm
