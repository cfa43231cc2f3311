#include "pfdm/report/interval_calibration.h"

#include <algorithm>

#include "gtest/gtest.h"
#include "pfdm/report/number_sd.h"

namespace pfdm {
namespace {

bool Has(const std::string& key) {
  const std::vector<std::string>& keys = CalibratedIntervalKeys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// The five numbers of docs/uncertainty_calibration.md that covered, under
// the names fit.json gives them; EDV, GCS and GLS, which did not, absent.
TEST(IntervalCalibrationTest, TheFiveThatCoveredUnderFitJsonsNames) {
  EXPECT_EQ(CalibratedIntervalKeys().size(), 5u);
  const std::vector<std::string>& clinical = ClinicalFieldNames();
  for (const char* key : {"net_twist_deg", "longitudinal_shortening_percent",
                          "radial_contraction_percent"}) {
    EXPECT_TRUE(Has(key)) << key;
    EXPECT_NE(std::find(clinical.begin(), clinical.end(), key), clinical.end())
        << key << " is no clinical field";
  }
  EXPECT_TRUE(Has("ratio"));
  EXPECT_TRUE(Has("esv_ml"));
  for (const char* key :
       {"edv_ml", "gcs_percent", "gls_percent", "lv_mass_g", "ecc_percent"}) {
    EXPECT_FALSE(Has(key)) << key;
  }
}

}  // namespace
}  // namespace pfdm
