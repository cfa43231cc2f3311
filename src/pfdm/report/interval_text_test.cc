#include "pfdm/report/interval_text.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(IntervalTextTest, PlusMinusIsTheHalfWidth) {
  EXPECT_EQ(PlusMinus(1.0, 2), " &plusmn; 1.96");
  EXPECT_EQ(PlusMinus(0.5, 1), " &plusmn; 1.0");
  EXPECT_EQ(PlusMinus(0.5, 1, Calibration::kNotCalibrated),
            " &plusmn; 1.0<sup title=\"not calibrated on this kind of data "
            "(docs/uncertainty_calibration.md)\">*</sup>");
  EXPECT_EQ(PlusMinus(kNotMeasured, 1), "");
}

TEST(IntervalTextTest, SdsOnlyWhenComputed) {
  FitAnalysis analysis;
  analysis.clinical.resize(2);
  analysis.region_motion.assign(2, std::vector<RegionMotion>(3));
  analysis.region_motion[1][2].ecc_percent = -12.0;
  analysis.region_motion[0][2].ecc_percent = -1.0;
  EXPECT_TRUE(
      std::isnan(ClinicalSd(analysis, 1, &ClinicalSummary::net_twist_deg)));
  EXPECT_EQ(IntervalNoteHtml(analysis), "");
  analysis.sd.computed = true;
  analysis.sd.clinical.resize(2);
  analysis.sd.clinical[1].net_twist_deg = 0.7;
  analysis.sd.region_motion = analysis.region_motion;
  EXPECT_EQ(ClinicalSd(analysis, 1, &ClinicalSummary::net_twist_deg), 0.7);
  EXPECT_EQ(RegionSd(analysis, 1, 2, &RegionMotion::ecc_percent), -12.0);
  EXPECT_TRUE(std::isnan(RegionSd(analysis, 2, 2, &RegionMotion::ecc_percent)));
  EXPECT_NE(IntervalNoteHtml(analysis).find("uncertain"), std::string::npos);
  EXPECT_EQ(PeakEccFrame(analysis, 2), 1);
}

}  // namespace
}  // namespace pfdm
