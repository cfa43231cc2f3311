#include "pfdm/report/reference_rings.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/material_myocardium.h"
#include "pfdm/report/number_sd.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// What the rings keep is what measuring the reference anew gives, and a
// second look-up returns it again, not another measurement.
TEST(ReferenceRingsTest, KeepsWhatMeasuringAnewGives) {
  const Model reference = UnevenTestModel(TestShell(9), 1.0, 0.01);
  ReferenceRings rings(reference);
  const double u = rings.At(0.5, -1.0);
  EXPECT_EQ(u, RingAtHeightFraction(reference, 0.5, -1.0));
  EXPECT_EQ(rings.At(0.5, -1.0), u);
  const MaterialRing& ring = rings.Ring(u, 36, -1.0);
  const MaterialRing fresh = SampleRing(reference, u, 36, -1.0);
  ASSERT_EQ(ring.points.size(), 36u);
  EXPECT_EQ(ring.points, fresh.points);
  EXPECT_EQ(&rings.Ring(u, 36, -1.0), &ring);
  // Another surface or another count is another ring.
  EXPECT_NE(rings.Ring(u, 36, 1.0).points, ring.points);
  EXPECT_EQ(rings.Ring(u).points.size(), static_cast<size_t>(kRingSamples));
  EXPECT_EQ(rings.Thickness(u), MeanWallThickness(reference, u));
  EXPECT_GT(rings.Thickness(u), 0.0);
  EXPECT_EQ(rings.MyocardiumMl(0.0, 0.5),
            MaterialMyocardiumMl(reference, 0.0, 0.5));
}

// One frame's summary after another with the rings kept is the summary
// with the rings found anew, to the bit: the delta method's steps keep them.
TEST(ReferenceRingsTest, KeptRingsSummarizeAsFreshOnes) {
  const Model reference = UnevenTestModel(TestShell(9), 1.0, 0.01);
  ReferenceRings rings(reference);
  for (double scale : {0.9, 0.8}) {
    const Model current = UnevenTestModel(TestShell(9), scale, 0.03);
    ClinicalSummary kept =
        SummarizeFrame(1, rings, current, RingSpan(), /*flat=*/true);
    ClinicalSummary fresh =
        SummarizeFrame(1, reference, current, RingSpan(), /*flat=*/true);
    const std::vector<double*> a = ClinicalFields(&kept);
    const std::vector<double*> b = ClinicalFields(&fresh);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      if (std::isnan(*b[i])) {
        EXPECT_TRUE(std::isnan(*a[i])) << i;
      } else {
        EXPECT_EQ(*a[i], *b[i]) << i;
      }
    }
    EXPECT_GT(kept.radial_contraction_percent, 5.0);
    EXPECT_NE(kept.wall_thickening_percent, 0.0);
    EXPECT_GT(kept.net_twist_deg, 0.1);
  }
}

}  // namespace
}  // namespace pfdm
