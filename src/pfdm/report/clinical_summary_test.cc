#include "pfdm/report/clinical_summary.h"

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {
namespace {

TEST(ClinicalSummaryTest, PhantomTruthReadsAsDesigned) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  const ClinicalSummary ed =
      SummarizeFrame(0, phantom.truth[0], phantom.truth[0]);
  EXPECT_EQ(ed.net_twist_deg, 0.0);
  EXPECT_EQ(ed.longitudinal_shortening_percent, 0.0);

  const ClinicalSummary es =
      SummarizeFrame(4, phantom.truth[0], phantom.truth[4]);
  // tau = -5 + 7 h degrees at height fraction h (knots are uniform in h on
  // frame 0), and rings turn about their centres: the apical ring (h = 0.2)
  // and the basal one (h = 0.85).  The rings are ellipses that shrink more
  // along x than y, which turns their points' angles by up to 0.005 degree.
  EXPECT_NEAR(es.apex_rotation_deg, -5.0 + 7.0 * 0.2, 0.01);
  EXPECT_NEAR(es.base_rotation_deg, -5.0 + 7.0 * 0.85, 0.01);
  EXPECT_NEAR(es.net_twist_deg, 7.0 * 0.65, 0.01);
  // a3 x 0.8 everywhere; the base rim's centre also drifts 1.5 mm across.
  EXPECT_NEAR(es.longitudinal_shortening_percent, 20.0, 0.05);
  // a1 x 0.8 and a2 x 0.8 to 0.9 from apex to base.
  EXPECT_GT(es.radial_contraction_percent, 17.0);
  EXPECT_LT(es.radial_contraction_percent, 20.0);
  for (double ratio : es.radial_ratio_x) EXPECT_NEAR(ratio, 0.8, 1e-12);
  EXPECT_NEAR(es.radial_ratio_y.back(), 0.9, 1e-12);  // Base: 10 % along y.
  // Torsion over the rings' distance, 0.65 of the 110 mm length.
  EXPECT_NEAR(es.torsion_deg_per_cm, es.net_twist_deg / (0.65 * 11.0), 1e-3);
  EXPECT_GT(es.shear_angle_deg, 0.0);
  EXPECT_LT(es.shear_angle_deg, es.net_twist_deg);
}

}  // namespace
}  // namespace pfdm

namespace pfdm {
namespace {

TEST(ClinicalSummaryTest, VolumeAndEjectionFractionFollowTheFrames) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  const std::vector<ClinicalSummary> summaries =
      SummarizeSequence(phantom.truth);
  ASSERT_EQ(summaries.size(), phantom.truth.size());
  // Radii and length shrink over systole: the volume falls every frame.
  for (size_t t = 1; t < summaries.size(); ++t) {
    EXPECT_LT(summaries[t].volume_ml, summaries[t - 1].volume_ml) << t;
  }
  const EjectionFraction ef = EjectionFractionOf(summaries);
  EXPECT_EQ(ef.ed_frame, 0);
  EXPECT_EQ(ef.es_frame, 4);
  EXPECT_DOUBLE_EQ(ef.edv_ml, summaries[0].volume_ml);
  EXPECT_DOUBLE_EQ(ef.ratio,
                   1.0 - summaries[4].volume_ml / summaries[0].volume_ml);
  // a1 x 0.8, a2 x 0.8..0.9, a3 x 0.8: about 1 - 0.8 x 0.85 x 0.8 = 0.456
  // (offsets and bending change the volume little).
  EXPECT_NEAR(ef.ratio, 0.456, 0.02);
}

TEST(ClinicalSummaryTest, EndSystoleIsTheSmallestVolumeWhereverItFalls) {
  std::vector<ClinicalSummary> summaries(5);
  const double volumes[] = {150, 120, 60, 90, 140};
  for (int t = 0; t < 5; ++t) {
    summaries[t].frame = t;
    summaries[t].volume_ml = volumes[t];
  }
  const EjectionFraction ef = EjectionFractionOf(summaries);
  EXPECT_EQ(ef.es_frame, 2);
  EXPECT_DOUBLE_EQ(ef.esv_ml, 60.0);
  EXPECT_DOUBLE_EQ(ef.ratio, 0.6);
  EXPECT_EQ(EjectionFractionOf({}).ratio, 0.0);
}

// --ed_frame: a sequence that starts mid-cycle reads EDV at the frame given;
// ES stays the least volume.  An ED outside the frames gives zeros.
TEST(ClinicalSummaryTest, EndDiastoleIsTheFrameGiven) {
  std::vector<ClinicalSummary> summaries(5);
  const double volumes[] = {90, 140, 150, 120, 60};
  for (int t = 0; t < 5; ++t) {
    summaries[t].frame = t;
    summaries[t].volume_ml = volumes[t];
  }
  const EjectionFraction ef = EjectionFractionOf(summaries, 2);
  EXPECT_EQ(ef.ed_frame, 2);
  EXPECT_DOUBLE_EQ(ef.edv_ml, 150.0);
  EXPECT_EQ(ef.es_frame, 4);
  EXPECT_DOUBLE_EQ(ef.ratio, 0.6);
  EXPECT_NEAR(EjectionFractionOf(summaries).ratio, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(EjectionFractionOf(summaries, 5).ratio, 0.0);
  EXPECT_EQ(EjectionFractionOf(summaries, -1).edv_ml, 0.0);
}

}  // namespace
}  // namespace pfdm
