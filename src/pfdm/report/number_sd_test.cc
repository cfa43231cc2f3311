#include "pfdm/report/number_sd.h"

#include <algorithm>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Each list of fields has its names in the same order: the volume's field
// is named volume_ml, a segment's thickening thickening_percent, GCS
// gcs_percent.
TEST(NumberSdTest, FieldsAndNamesLineUp) {
  ClinicalSummary clinical;
  const std::vector<double*> c = ClinicalFields(&clinical);
  ASSERT_EQ(c.size(), ClinicalFieldNames().size());
  const auto volume = std::find(c.begin(), c.end(), &clinical.volume_ml);
  ASSERT_NE(volume, c.end());
  EXPECT_EQ(ClinicalFieldNames()[volume - c.begin()], "volume_ml");
  RegionMotion motion;
  const std::vector<double*> r = RegionFields(&motion);
  ASSERT_EQ(r.size(), RegionFieldNames().size());
  EXPECT_EQ(RegionFieldNames()[std::find(r.begin(), r.end(),
                                         &motion.thickening_percent) -
                               r.begin()],
            "thickening_percent");
  GlobalStrain strain;
  const std::vector<double*> g = StrainFields(&strain);
  ASSERT_EQ(g.size(), StrainFieldNames().size());
  EXPECT_EQ(
      StrainFieldNames()[std::find(g.begin(), g.end(), &strain.gcs_percent) -
                         g.begin()],
      "gcs_percent");
}

}  // namespace
}  // namespace pfdm
