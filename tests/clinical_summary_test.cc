#include "pfdm/clinical_summary.h"

#include "gtest/gtest.h"
#include "pfdm/phantom.h"

namespace pfdm {
namespace {

TEST(ClinicalSummaryTest, PhantomTruthReadsAsDesigned) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  const ClinicalSummary ed = SummarizeFrame(0, phantom.truth[0], phantom.truth[0]);
  EXPECT_EQ(ed.net_twist_deg, 0.0);
  EXPECT_EQ(ed.longitudinal_shortening_percent, 0.0);

  const ClinicalSummary es = SummarizeFrame(4, phantom.truth[0], phantom.truth[4]);
  // Twist -5 degrees at the apex knot, +2 at the base: the apical ring is
  // knot 1, 1/16 of the way up.
  EXPECT_NEAR(es.base_rotation_deg, 2.0, 1e-9);
  EXPECT_NEAR(es.apex_rotation_deg, -5.0 + 7.0 / 16.0, 1e-9);
  EXPECT_NEAR(es.net_twist_deg, 7.0 - 7.0 / 16.0, 1e-9);
  EXPECT_NEAR(es.longitudinal_shortening_percent, 20.0, 1e-9);
  EXPECT_NEAR(es.radial_contraction_x_percent, 20.0, 1e-9);
  for (double ratio : es.radial_ratio_x) EXPECT_NEAR(ratio, 0.8, 1e-12);
  EXPECT_NEAR(es.radial_ratio_y.back(), 0.9, 1e-12);  // Base: 10 % along y.
  EXPECT_EQ(ApicalKnot(phantom.truth[0].config), 1);
}

}  // namespace
}  // namespace pfdm
