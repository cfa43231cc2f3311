#include "pfdm/phantom/lv_truth.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

std::vector<Eigen::Vector3d> Moved(const std::vector<Eigen::Vector3d>& points,
                                   const Eigen::Affine3d& move) {
  std::vector<Eigen::Vector3d> result;
  for (const Eigen::Vector3d& x : points) result.push_back(move * x);
  return result;
}

// The meter on transforms whose every number is known.
TEST(LvPhantomTruthTest, ScalingAboutTheApexShortensAndContracts) {
  const LvShape shape;
  const LvTruthMeter meter(shape);
  const Eigen::Affine3d pose(
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const auto world0 = Moved(meter.material(), pose);
  const LvFrameTruth same = meter.Measure(world0, world0);
  EXPECT_NEAR(same.length_mm, 95.0, 1e-9);
  EXPECT_NEAR(same.volume_ml, shape.ClosedVolume(0.0) / 1000.0,
              1e-3 * same.volume_ml);
  EXPECT_EQ(same.midwall.rotation_deg.size(), 20u);
  EXPECT_EQ(same.segments.size(), 16u);
  EXPECT_EQ(same.segments[0].name, "basal 1");
  EXPECT_EQ(same.segments[6].name, "mid 1");
  EXPECT_EQ(same.segments[15].name, "apical 4");

  const LvFrameTruth scaled = meter.Measure(
      world0, Moved(meter.material(), pose * Eigen::Scaling(0.9)));
  EXPECT_NEAR(scaled.longitudinal_shortening_percent, 10.0, 1e-9);
  EXPECT_NEAR(scaled.volume_ml / same.volume_ml, 0.729, 1e-12);
  EXPECT_NEAR(scaled.myocardial_volume_ml / same.myocardial_volume_ml, 0.729,
              1e-12);
  for (const LvLayerRings* rings :
       {&scaled.midwall, &scaled.endo, &scaled.epi}) {
    for (size_t i = 0; i < rings->rotation_deg.size(); ++i) {
      EXPECT_NEAR(rings->radial_contraction_percent[i], 10.0, 1e-9);
      EXPECT_NEAR(rings->rotation_deg[i], 0.0, 1e-9);
    }
  }
  for (const LvSegmentTruth& segment : scaled.segments) {
    EXPECT_NEAR(segment.radial_contraction_percent, 10.0, 1e-9);
  }
}

TEST(LvPhantomTruthTest, SpinAboutTheAxisReadsAsRotationShiftsDoNot) {
  const LvShape shape;
  const LvTruthMeter meter(shape);
  const auto world0 = meter.material();
  const Eigen::Affine3d spin_and_shift =
      Eigen::Translation3d(3.0, -4.0, 7.0) *
      Eigen::AngleAxisd(12.0 * kPi / 180.0, Eigen::Vector3d::UnitZ());
  const LvFrameTruth truth =
      meter.Measure(world0, Moved(meter.material(), spin_and_shift));
  EXPECT_NEAR(truth.longitudinal_shortening_percent, 0.0, 1e-9);
  EXPECT_NEAR(truth.volume_ml, meter.Measure(world0, world0).volume_ml, 1e-9);
  for (const LvLayerRings* rings : {&truth.midwall, &truth.endo, &truth.epi}) {
    for (size_t i = 0; i < rings->rotation_deg.size(); ++i) {
      EXPECT_NEAR(rings->rotation_deg[i], 12.0, 1e-9);
      EXPECT_NEAR(rings->radial_contraction_percent[i], 0.0, 1e-9);
    }
  }
  for (const LvSegmentTruth& segment : truth.segments) {
    EXPECT_NEAR(segment.rotation_deg, 12.0, 1e-9);
  }
}

TEST(LvPhantomTruthTest, RingValuesInterpolateAndExtrapolateToTheApex) {
  std::vector<double> values;
  for (double h : LvRingHeights()) values.push_back(3.0 - 2.0 * h);
  for (double h : {0.0, 0.01, 0.05, 0.333, 0.5, 0.97, 1.0}) {
    EXPECT_NEAR(LvRingValueAt(values, h), 3.0 - 2.0 * h, 1e-12) << h;
  }
  values[9] = 10.0;  // h = 0.5
  EXPECT_NEAR(LvRingValueAt(values, 0.5), 10.0, 1e-12);
  EXPECT_NEAR(LvRingValueAt(values, 0.475), 0.5 * (3.0 - 0.9 + 10.0), 1e-12);
}

// The phantom's sectors run counter-clockwise from the body's -x, the AHA
// segments clockwise from the anterior insertion, 60 degrees on
// (lv_phantom.h): mid 2, the lesion's, is mid anteroseptal (AHA 8) either
// way, its neighbours trade places, and the map is its own inverse.
TEST(LvPhantomTruthTest, SectorsMapToAhaSegmentsAndBack) {
  EXPECT_EQ(LvAhaSegmentIndex(7), 7);
  EXPECT_EQ(LvAhaSegmentIndex(6), 8);
  EXPECT_EQ(LvAhaSegmentIndex(8), 6);
  EXPECT_EQ(LvAhaSegmentIndex(0), 2);
  EXPECT_EQ(LvAhaSegmentIndex(3), 5);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(LvAhaSegmentIndex(LvAhaSegmentIndex(k)), k);
    EXPECT_EQ(LvAhaSegmentIndex(k) / 6, k / 6);
  }
}

}  // namespace
}  // namespace pfdm
