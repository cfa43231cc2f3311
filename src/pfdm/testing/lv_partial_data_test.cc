// Fits of partial data from the independent LV phantom: a mid-ventricular
// segment without the apex (tags, or three short-axis slices) and a
// short-axis stack without long-axis views.  The long axis is the data's
// (start_axis.h), not their largest spread, which lies across a squat
// segment; what the fit says of the apex is marked extrapolated
// (apex_coverage.h).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/apex_coverage.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

struct PartialFit {
  LvPhantom phantom;
  SequenceFit fit;
  std::vector<ClinicalSummary> clinical;
};

PartialFit FitPartial(LvRegion region, LvSampling sampling,
                      LvTagLayer tags = LvTagLayer::kMidwall,
                      int num_slices = 0, int num_long_axis_planes = 0) {
  LvPhantomOptions options;
  options.region = region;
  options.sampling = sampling;
  options.tags = tags;
  options.num_tags = 1500;
  options.num_slices = num_slices;
  options.num_long_axis_planes = num_long_axis_planes;
  PartialFit result{MakeLvPhantom(options), {}, {}};
  result.fit =
      FitSequence(result.phantom.points, ModelConfig::Paper(17), FitOptions());
  std::vector<Model> models;
  for (size_t t = 0; t < result.fit.frames.size(); ++t) {
    models.push_back(result.fit.ModelAt(t));
  }
  result.clinical = SummarizeSequence(models);
  return result;
}

// Degrees between frame 0's fitted axis and the phantom's, apex to base.
double AxisErrorDeg(const PartialFit& f) {
  const Eigen::Vector3d truth =
      f.phantom.truth[0].world_from_body.linear().col(2);
  const Eigen::Vector3d fitted = f.fit.ModelAt(0).Rotation().col(2);
  return std::acos(std::clamp(truth.dot(fitted), -1.0, 1.0)) * kDegrees;
}

// The phantom's rotation (mid-wall rings, last frame) at the ED heights of
// the fitted model's ring at `fraction` of its frame-0 length from its apex
// pole: the truth of what the fit's ring measured.
double TruthRotationAtFittedRing(const PartialFit& f, double fraction) {
  const Model model = f.fit.ModelAt(0);
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0);
  double length = 0.0;
  for (int k = 0; k < 36; ++k) {
    length +=
        axis.dot(model.WorldPoint(model.config.u_max, k * M_PI / 18) - apex) /
        36;
  }
  const Eigen::Vector3d body = f.phantom.truth[0].world_from_body.inverse() *
                               (apex + fraction * length * axis);
  const double h = body.z() / LvShape(f.phantom.options.shape).base_z();
  EXPECT_GE(h, 0.0);
  EXPECT_LE(h, 1.0);
  return LvRingValueAt(f.phantom.truth.back().midwall.rotation_deg,
                       std::clamp(h, 0.0, 1.0));
}

void Print(const char* name, const PartialFit& f) {
  const ClinicalSummary& es = f.clinical.back();
  const double apex = TruthRotationAtFittedRing(f, kApicalRingFraction);
  const double base = TruthRotationAtFittedRing(f, kBasalRingFraction);
  std::printf(
      "%s: axis %.2f deg off (%s); apex in data %d (nearest %.3f, lowest "
      "%.3f, u %.3f); rms %.2f..%.2f; ES apex %.2f (%.2f) base %.2f (%.2f) "
      "twist %.2f (%.2f; apex to base %.2f) torsion %.3f deg/cm\n",
      name, AxisErrorDeg(f), f.fit.axis_source.c_str(), f.fit.apex_in_data,
      f.fit.apex_data_distance, f.fit.lowest_data_height, f.fit.lowest_data_u,
      f.fit.frames.front().rms_mm, f.fit.frames.back().rms_mm,
      es.apex_rotation_deg, apex, es.base_rotation_deg, base, es.net_twist_deg,
      base - apex, f.phantom.truth.back().net_twist_deg, es.torsion_deg_per_cm);
}

// Mid-ventricular tags (ED heights 30-72 %: 40 mm long, 45-54 mm across):
// their largest spread lies across the ventricle, 89-90 degrees off, and
// gave a twist of the wrong sign and frame 0 unsettled (closest points
// moving 9 mm in its last search).  The candidate axes' fits find the axis
// (0.85 degrees off; 0.0-0.8 over 13 seeds), frame 0 fits at the noise
// (0.49 mm), and the net twist (the fit's rings at 0.2 and 0.85 of its own
// length, which spans the data and the cup it closes below them) has the
// truth's sign and reads the truth at those rings' heights within 1 degree
// (4.8 against 5.7; the whole LV's 13 degrees are not in these data);
// torsion 1.16 deg/cm against 1.37.  The fit says the apex is not in the
// data.
TEST(LvPartialDataTest, MidventricularTagsFindTheAxisAndTheTwist) {
  const PartialFit f = FitPartial(LvRegion::kMidventricular, LvSampling::kTags);
  Print("mid-ventricular tags", f);
  EXPECT_LT(AxisErrorDeg(f), 10.0);
  EXPECT_EQ(f.fit.axis_source, "point cloud, best of 9 candidate axes");
  EXPECT_FALSE(f.fit.frames[0].verdict.Has(kTopSliceCode));  // Not a plane.
  EXPECT_LT(f.fit.frames[0].rms_mm, 0.55);
  EXPECT_LT(f.fit.frames[0].unsettled_mm, 0.5);
  EXPECT_FALSE(f.fit.apex_in_data);
  EXPECT_GT(f.fit.apex_data_distance, 0.3);
  EXPECT_GT(f.fit.lowest_data_height, kApexReach);
  const ClinicalSummary& es = f.clinical.back();
  const double truth = TruthRotationAtFittedRing(f, kBasalRingFraction) -
                       TruthRotationAtFittedRing(f, kApicalRingFraction);
  EXPECT_GT(es.net_twist_deg, 0.0);  // The truth's sign.
  EXPECT_NEAR(es.net_twist_deg, truth, 1.5);
  EXPECT_NEAR(es.torsion_deg_per_cm, 13.0 / 9.5, 0.3);
}

// The same segment's tags through the wall (64 mm across): their spread
// across the wall (3 mm RMS) leaves the candidates' screened costs within
// 25 % of each other; the close calls fitted on find the axis (0.65
// degrees off; 0.2-1.1 over 13 seeds, one of which screening alone had
// upside down), and the twist reads the truth at the fit's rings (4.87
// against 4.86).
TEST(LvPartialDataTest, MidventricularTagsThroughTheWall) {
  const PartialFit f = FitPartial(LvRegion::kMidventricular, LvSampling::kTags,
                                  LvTagLayer::kWall);
  Print("mid-ventricular wall tags", f);
  EXPECT_LT(AxisErrorDeg(f), 10.0);
  EXPECT_TRUE(f.fit.config.Solid());
  EXPECT_FALSE(f.fit.apex_in_data);
  const double truth = TruthRotationAtFittedRing(f, kBasalRingFraction) -
                       TruthRotationAtFittedRing(f, kApicalRingFraction);
  EXPECT_GT(f.clinical.back().net_twist_deg, 0.0);
  EXPECT_NEAR(f.clinical.back().net_twist_deg, truth, 1.5);
}

// The fit's volume at ED against the phantom's mid-wall's.
double EdVolumeShortfall(const PartialFit& f) {
  return 1.0 - f.clinical[0].volume_ml / f.phantom.truth[0].volume_ml;
}

// A short-axis stack of 9 mid-wall contours, 5 to 90 % up, no long-axis
// views: the slices' normal (0.06 degrees off); the lowest slice, 11 % of
// the length from the apex pole, counts as the apex.  The model ends at the
// highest slice, the base 10 % of the length above it is not in the data,
// and every frame says so (top_slice): the mid-wall's volume at ED reads
// 11 % under the truth's (145.6 ml against 163.1).
TEST(LvPartialDataTest, ShortAxisStackGivesTheAxis) {
  const PartialFit f = FitPartial(LvRegion::kFull, LvSampling::kSaxSlices);
  Print("sax stack", f);
  EXPECT_LT(AxisErrorDeg(f), 10.0);
  EXPECT_EQ(f.fit.axis_source, "normal of 9 parallel planes");
  EXPECT_TRUE(f.fit.apex_in_data);
  EXPECT_LT(f.fit.apex_data_distance, kApexReach);
  for (size_t t = 0; t < f.fit.frames.size(); ++t) {
    EXPECT_TRUE(f.fit.frames[t].verdict.Has(kTopSliceCode)) << t;
  }
  std::printf("sax stack: ED volume %.1f ml against %.1f\n",
              f.clinical[0].volume_ml, f.phantom.truth[0].volume_ml);
  EXPECT_GT(EdVolumeShortfall(f), 0.05);
  // Where a segmentation's labels close the base, nothing is said.
  PointSequence labelled = f.phantom.points;
  labelled.base_from_labels = true;
  const SequenceFit fit =
      FitSequence(labelled, ModelConfig::Paper(17), FitOptions());
  EXPECT_FALSE(fit.frames[0].verdict.Has(kTopSliceCode));
}

// The same stack with three long-axis planes, whose contours reach the
// base: no frame ends in a slice, and the volume at ED is the truth's
// (162.2 ml against 163.1).  On frame 3 the base has come
// down to the top slice and the planes' contours end within 2 mm of it:
// 6 % of the top band's points lie below it.
TEST(LvPartialDataTest, LongAxisPlanesReachTheBase) {
  const PartialFit f =
      FitPartial(LvRegion::kFull, LvSampling::kSaxSlices, LvTagLayer::kMidwall,
                 /*num_slices=*/0, /*num_long_axis_planes=*/3);
  for (size_t t = 0; t < f.fit.frames.size(); ++t) {
    EXPECT_FALSE(f.fit.frames[t].verdict.Has(kTopSliceCode)) << t;
  }
  std::printf(
      "sax stack and 3 long-axis planes: ED volume %.1f ml against "
      "%.1f\n",
      f.clinical[0].volume_ml, f.phantom.truth[0].volume_ml);
  EXPECT_LT(std::abs(EdVolumeShortfall(f)), 0.03);
}

// Endocardial and epicardial contours of the same stack: a solid, on the
// same axis.
TEST(LvPartialDataTest, ShortAxisStackOfBothWalls) {
  const PartialFit f =
      FitPartial(LvRegion::kFull, LvSampling::kSaxSlices, LvTagLayer::kWall);
  Print("sax stack walls", f);
  EXPECT_LT(AxisErrorDeg(f), 10.0);
  EXPECT_TRUE(f.fit.config.Solid());
  EXPECT_EQ(f.fit.axis_source, "normal of 9 parallel planes");
}

// Three short-axis slices of the mid-ventricular segment (the largest
// spread across, 144 degrees off before): their normal, and no apex.
TEST(LvPartialDataTest, MidventricularSlicesGiveTheAxis) {
  const PartialFit f =
      FitPartial(LvRegion::kMidventricular, LvSampling::kSaxSlices);
  Print("mid-ventricular slices", f);
  EXPECT_LT(AxisErrorDeg(f), 10.0);
  EXPECT_EQ(f.fit.axis_source, "normal of 3 parallel planes");
  EXPECT_FALSE(f.fit.apex_in_data);
}

// Three short-axis slices of the whole LV: at end-systole the base has
// descended below the basal slice and the data span half of frame 0's
// length in mm.  The frame says so (short_span), and its volume, ESV and
// the ratio are n/a; --extrapolated shows them.  With the length held at
// frame 0's the fit's continuation above the data enclosed far more than
// the truth at an RMS under the noise (the mid-wall's volume fraction 0.26
// against 0.49); with the length the data's (the apex in them), the model
// ends at the highest slice left, under the base, and the fraction reads
// high (0.53): either way the volume above the data is not measured.
TEST(LvPartialDataTest, ThreeSlicesThatLoseTheBaseHaveNoEndSystolicVolume) {
  const PartialFit f = FitPartial(LvRegion::kFull, LvSampling::kSaxSlices,
                                  LvTagLayer::kMidwall, /*num_slices=*/3);
  // The data are the mid-wall's, and so is the volume the fit encloses.
  const std::vector<LvFrameTruth>& truth = f.phantom.truth;
  const size_t es = f.fit.frames.size() - 1;
  for (size_t t = 0; t < es; ++t) {
    ASSERT_GT(truth[t].volume_ml, truth[es].volume_ml);
  }
  const double ejection = 1.0 - truth[es].volume_ml / truth[0].volume_ml;
  EXPECT_TRUE(f.fit.frames[es].verdict.Has(kShortSpanCode));
  for (size_t t = 0; t < es; ++t) {
    EXPECT_FALSE(f.fit.frames[t].verdict.Has(kShortSpanCode)) << t;
  }
  const FitAnalysis analysis = AnalyzeFit(f.fit);
  EXPECT_FALSE(analysis.volume_measured[es]);
  EXPECT_FALSE(Measured(analysis.clinical[es].volume_ml));
  EXPECT_FALSE(Measured(analysis.ejection_fraction.ratio));
  EXPECT_TRUE(Measured(analysis.ejection_fraction.edv_ml));
  // Shown, the end-systolic cavity lacks what lies above the highest
  // slice: the ejection fraction reads over the truth's.
  const FitAnalysis shown =
      AnalyzeFit(f.fit, {}, RegionLayout(), /*show_extrapolated=*/true);
  std::printf(
      "three slices, shown: mid-wall volume fraction %.3f against "
      "%.3f\n",
      shown.ejection_fraction.ratio, ejection);
  EXPECT_GT(shown.ejection_fraction.ratio, ejection + 0.02);
}

}  // namespace
}  // namespace pfdm
