#include "pfdm/report/key_numbers.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// Two frames of a cavity fit of tags on the mid-wall: the ejection
// fraction's, EDV's, peak GLS's, twist's, torsion's and contraction's
// intervals plain, ESV's, peak GCS's, the mass's and thickening's starred
// as not calibrated on that kind of data (interval_calibration.h); on data
// of no calibrated kind every interval is starred.
TEST(KeyNumbersTest, StarsTheIntervalsThatAreNotCalibrated) {
  SequenceFit fit;
  FitAnalysis analysis;
  analysis.interval_data = IntervalData::kMidwallTags;
  analysis.volume_surface = "cavity";
  analysis.ejection_fraction = {0, 1, 150.0, 60.0, 0.6};
  analysis.clinical.resize(2);
  analysis.strain.resize(2);
  analysis.strain[1].gcs_percent = -18.0;
  analysis.strain[1].gls_percent = -15.0;
  analysis.sd.computed = true;
  analysis.sd.ejection_fraction = {0, 1, 1.0, 1.0, 0.01};
  analysis.sd.clinical.resize(2);
  analysis.sd.strain.resize(2);
  analysis.sd.strain[1].gcs_percent = 1.0;
  analysis.sd.strain[1].gls_percent = 1.0;
  const std::string html = KeyNumbersHtml(fit, analysis);
  const std::string star =
      "<sup title=\"not calibrated on this kind of data "
      "(docs/uncertainty_calibration.md)\">*</sup>";
  EXPECT_NE(html.find("60.0 &plusmn; 2.0 %</b>"), std::string::npos) << html;
  EXPECT_NE(html.find("EDV 150.0 &plusmn; 2.0 ml"), std::string::npos);
  // ESV's held the noise-free fit in 95 % of 300 draws: calibrated.
  EXPECT_NE(html.find("ESV 60.0 &plusmn; 2.0 ml"), std::string::npos);
  // Peak GCS's interval held the noise-free fit in 99 % of draws: too wide.
  EXPECT_NE(html.find("-18.0 &plusmn; 2.0" + star + " %</b>"),
            std::string::npos);
  EXPECT_NE(html.find("-15.0 &plusmn; 2.0 %</b>"), std::string::npos);
  // The default config is the paper's solid, so the mass and thickening
  // cards show: not calibrated on mid-wall tags.
  ASSERT_TRUE(fit.config.Solid());
  EXPECT_NE(html.find("torsion at ES<b>0.00 &plusmn; 0.00&deg;/cm</b>"),
            std::string::npos);
  EXPECT_NE(html.find("net twist at ES<b>0.0 &plusmn; 0.0&deg;</b>"),
            std::string::npos);
  EXPECT_NE(html.find("radial contraction at ES<b>0.0 &plusmn; 0.0 %</b>"),
            std::string::npos);
  EXPECT_EQ(CountOf(html, star), 3) << html;  // GCS, mass, thickening.
  // Data of no calibrated kind (tags and contours mixed): all eleven
  // starred.
  analysis.interval_data = IntervalData::kOther;
  EXPECT_EQ(CountOf(KeyNumbersHtml(fit, analysis), star), 11);
  // Without intervals, no star and no plus-minus.
  analysis.sd = NumberSd();
  EXPECT_EQ(KeyNumbersHtml(fit, analysis).find("plusmn"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
