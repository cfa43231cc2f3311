#include "pfdm/report/report_text.h"

#include "gtest/gtest.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {
namespace {

TEST(ReportTextTest, FixedSaysNaForWhatIsNotMeasuredAndNeverMinusZero) {
  EXPECT_EQ(Fixed(3.14159, 2), "3.14");
  EXPECT_EQ(Fixed(-0.04, 1), "0.0");
  EXPECT_EQ(Fixed(-0.06, 1), "-0.1");
  EXPECT_EQ(Fixed(kNotMeasured, 1), "n/a");
  EXPECT_EQ(WithUnit(12.345, 1, "&deg;"), "12.3&deg;");
  EXPECT_EQ(WithUnit(kNotMeasured, 1, "&deg;"), "n/a");
}

TEST(ReportTextTest, TintIsOrangeUpBlueDownWhiteAtZero) {
  EXPECT_EQ(Tint(0.0, 10.0), " style=\"background:#ffffff\"");
  EXPECT_EQ(Tint(10.0, 10.0), " style=\"background:#ffb991\"");
  EXPECT_EQ(Tint(-20.0, 10.0), " style=\"background:#91b9ff\"");
  EXPECT_EQ(Tint(kNotMeasured, 10.0), "");
}

TEST(ReportTextTest, VolumeNameSaysWhatTheVolumeIsOf) {
  FitAnalysis analysis;
  analysis.volume_surface = "cavity";
  EXPECT_EQ(VolumeName(analysis), "cavity volume");
  analysis.volume_surface = "midwall";
  EXPECT_EQ(VolumeName(analysis), "mid-wall enclosed volume");
}

}  // namespace
}  // namespace pfdm
