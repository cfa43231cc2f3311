#include "pfdm/report/key_numbers.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// Two frames of a cavity fit: the ejection fraction's and ESV's intervals
// plain, EDV's, the mass's, thickening's, torsion's and the peak strains'
// starred as not calibrated (interval_calibration.h).
TEST(KeyNumbersTest, StarsTheIntervalsThatAreNotCalibrated) {
  SequenceFit fit;
  FitAnalysis analysis;
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
      "<sup title=\"not calibrated: read as a lower "
      "bound\">*</sup>";
  EXPECT_NE(html.find("60.0 &plusmn; 2.0 %</b>"), std::string::npos) << html;
  EXPECT_NE(html.find("EDV 150.0 &plusmn; 2.0" + star), std::string::npos);
  EXPECT_NE(html.find("ESV 60.0 &plusmn; 2.0" + star), std::string::npos);
  EXPECT_NE(html.find("-18.0 &plusmn; 2.0 %</b>"), std::string::npos);
  EXPECT_NE(html.find("-15.0 &plusmn; 2.0 %</b>"), std::string::npos);
  // The default config is the paper's solid: its mass, thickening and
  // torsion are not calibrated either; twist, contraction and shortening
  // are.
  ASSERT_TRUE(fit.config.Solid());
  EXPECT_NE(html.find("torsion at ES<b>0.00 &plusmn; 0.00" + star),
            std::string::npos);
  EXPECT_NE(html.find("net twist at ES<b>0.0 &plusmn; 0.0&deg;</b>"),
            std::string::npos);
  EXPECT_NE(html.find("radial contraction at ES<b>0.0 &plusmn; 0.0 %</b>"),
            std::string::npos);
  EXPECT_EQ(CountOf(html, star), 5)
      << html;  // EDV, ESV, mass, thickening, torsion.
  // Without intervals, no star and no plus-minus.
  analysis.sd = NumberSd();
  EXPECT_EQ(KeyNumbersHtml(fit, analysis).find("plusmn"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
