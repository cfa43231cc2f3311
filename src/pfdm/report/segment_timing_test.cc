#include "pfdm/report/segment_timing.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// 6 frames 40 ms apart; segments 1-16 peak (-20 %) alternately at frame 2
// (80 ms) and frame 4 (160 ms), -5 % in the other frames after ED;
// segment 4 has no Ecc in frame 3; the apex cap peaks at frame 5.
std::vector<std::vector<RegionMotion>> Constructed(
    const std::vector<WallRegion>& regions) {
  std::vector<std::vector<RegionMotion>> motion(
      6, std::vector<RegionMotion>(regions.size()));
  for (size_t r = 0; r < regions.size(); ++r) {
    const int peak = regions[r].level == kApex ? 5 : (r % 2 == 0 ? 2 : 4);
    for (int t = 1; t < 6; ++t) {
      motion[t][r].ecc_percent = t == peak ? -20.0 : -5.0;
    }
  }
  motion[3][3].ecc_percent = kNotMeasured;
  return motion;
}

TEST(SegmentTimingTest, TimeToPeakAndDyssynchronyOfKnownPeaks) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  ASSERT_EQ(regions.size(), 17u);
  const auto motion = Constructed(regions);
  const std::vector<double> times = {0, 40, 80, 120, 160, 200};
  const Dyssynchrony d = MeasureDyssynchrony(regions, motion, times, 0);
  ASSERT_EQ(d.peaks.size(), 17u);
  EXPECT_TRUE(d.in_ms);
  EXPECT_EQ(d.peaks[0].frame, 2);
  EXPECT_NEAR(d.peaks[0].time_to_peak, 80.0, 1e-12);
  EXPECT_NEAR(d.peaks[0].percent, -20.0, 1e-12);
  EXPECT_NEAR(d.peaks[1].time_to_peak, 160.0, 1e-12);
  EXPECT_EQ(d.peaks[3].frame, -1);  // n/a in frame 3.
  EXPECT_TRUE(std::isnan(d.peaks[3].time_to_peak));
  EXPECT_NEAR(d.peaks[16].time_to_peak, 200.0, 1e-12);  // Not counted.
  // 8 segments at 80 ms and 7 at 160 ms (segment 4, n/a, would be
  // the eighth): mean 117.33 ms, sample SD
  // sqrt((8 * 37.333^2 + 7 * 42.667^2) / 14) = 41.312 ms.
  EXPECT_EQ(d.segments, 15);
  EXPECT_NEAR(d.index, 41.312, 1e-3);

  // From ED at frame 1 (40 ms): every time 40 ms less, the spread the same.
  const Dyssynchrony from_1 = MeasureDyssynchrony(regions, motion, times, 1);
  EXPECT_NEAR(from_1.peaks[0].time_to_peak, 40.0, 1e-12);
  EXPECT_NEAR(from_1.index, 41.312, 1e-3);

  // Without times, in frames: 8 at 2 and 7 at 4, 41.312 / 40 frames.
  const Dyssynchrony frames = MeasureDyssynchrony(regions, motion, {}, 0);
  EXPECT_FALSE(frames.in_ms);
  EXPECT_NEAR(frames.peaks[1].time_to_peak, 4.0, 1e-12);
  EXPECT_NEAR(frames.index, 1.0328, 1e-4);
}

TEST(SegmentTimingTest, FewerThanTwoSegmentsHaveNoIndex) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  auto motion = Constructed(regions);
  for (size_t r = 1; r < regions.size(); ++r) {
    motion[1][r].ecc_percent = kNotMeasured;
  }
  const Dyssynchrony d = MeasureDyssynchrony(regions, motion, {}, 0);
  EXPECT_EQ(d.segments, 1);
  EXPECT_TRUE(std::isnan(d.index));
  EXPECT_NEAR(d.peaks[0].time_to_peak, 2.0, 1e-12);
}

}  // namespace
}  // namespace pfdm
