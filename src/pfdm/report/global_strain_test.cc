#include "pfdm/report/global_strain.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(GlobalStrainTest, AreaWeightedOverSegmentsAndLevels) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  std::vector<RegionMotion> motion(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    motion[r].area_mm2 = 100.0;
    motion[r].ecc_percent = regions[r].level == kBasal ? -10.0 : -20.0;
    motion[r].ell_percent = -15.0;
    motion[r].ecl_percent = 2.0;
  }
  motion[12].area_mm2 = 400.0;  // One apical segment four times as large.
  motion[12].ell_percent = -5.0;
  const GlobalStrain g = SummarizeStrain(regions, motion);
  // 6 basal x 100 at -10, 6 mid x 100 + 3 x 100 + 400 apical + the apex
  // cap's 100 at -20; the cap counts into the apical level.
  ASSERT_EQ(regions.size(), 17u);
  EXPECT_NEAR(g.gcs_percent, (-10.0 * 600 - 20.0 * 1400) / 2000, 1e-12);
  EXPECT_NEAR(g.gls_percent, (-15.0 * 1600 - 5.0 * 400) / 2000, 1e-12);
  EXPECT_NEAR(g.gcl_percent, 2.0, 1e-12);
  EXPECT_NEAR(g.level_ecc_percent[kBasal], -10.0, 1e-12);
  EXPECT_NEAR(g.level_ecc_percent[kApical], -20.0, 1e-12);
  EXPECT_NEAR(g.level_ell_percent[kApical], (-15.0 * 400 - 5.0 * 400) / 800,
              1e-12);
}

TEST(GlobalStrainTest, PeaksAreTheMostNegativeFrames) {
  std::vector<GlobalStrain> frames(4);
  frames[1].gcs_percent = -12.0;
  frames[2].gcs_percent = -18.5;
  frames[3].gcs_percent = -3.0;
  frames[1].gls_percent = -16.0;
  frames[2].gls_percent = -15.0;
  EXPECT_EQ(PeakGcs(frames).frame, 2);
  EXPECT_EQ(PeakGcs(frames).percent, -18.5);
  EXPECT_EQ(PeakGls(frames).frame, 1);
  EXPECT_EQ(PeakGls({}).frame, 0);
  std::vector<std::vector<RegionMotion>> motion(3,
                                                std::vector<RegionMotion>(2));
  motion[1][0].ecc_percent = -9.0;
  motion[2][0].ecc_percent = -4.0;
  motion[2][1].ecc_percent = 3.0;  // Stretching only: the peak stays 0.
  const std::vector<double> peak = PeakRegionEcc(motion);
  ASSERT_EQ(peak.size(), 2u);
  EXPECT_EQ(peak[0], -9.0);
  EXPECT_EQ(peak[1], 0.0);
}

}  // namespace
}  // namespace pfdm
