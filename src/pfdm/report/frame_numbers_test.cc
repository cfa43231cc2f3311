#include "pfdm/report/frame_numbers.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/report/number_uncertainty.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

void ExpectSameNumbers(const FrameNumbers& a, const FrameNumbers& b) {
  const std::vector<double> x = Flatten(a), y = Flatten(b);
  ASSERT_EQ(x.size(), y.size());
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(y[i])) {
      EXPECT_TRUE(std::isnan(x[i])) << i;
      continue;
    }
    EXPECT_NEAR(x[i], y[i], 1e-11 * (1.0 + std::abs(y[i]))) << i;
  }
}

class FrameMeasurerTest : public ::testing::TestWithParam<bool> {
 protected:
  // Midwall (false) or solid (true), 9 knots.
  Model Base() const { return GetParam() ? TestShell(9) : TestSpheroid(9); }
};

// A step of each knot (the first, the last, inner ones), of a global and
// of the pose, measured again only where it moves the model, gives what
// measuring the moved model from scratch gives, with the flat lid and with
// a tilted base plane.
TEST_P(FrameMeasurerTest, MovedMeasuresWhatMeasureFrameMeasures) {
  const Model ed = UnevenTestModel(Base(), 1.0, 0.01);
  const Model current = UnevenTestModel(Base(), 0.85, 0.03);
  const ReferenceSamples samples = SampleReference(ed, RegionLayout());
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  BasePlane plane;
  plane.point = current.WorldPoint(0.4, 0.0);
  plane.normal =
      (current.Rotation().col(2) + Eigen::Vector3d(0.1, 0, 0)).normalized();
  using Kind = CovarianceEntry::Kind;
  const std::vector<CovarianceEntry> entries = {
      {Kind::kKnot, 0, kA1}, {Kind::kKnot, 4, kA3},  {Kind::kKnot, 7, kTau},
      {Kind::kKnot, 8, kA2}, {Kind::kCenter, -1, 2}, {Kind::kRotation, -1, 0}};
  for (const BasePlane* base : {static_cast<const BasePlane*>(nullptr),
                                static_cast<const BasePlane*>(&plane)}) {
    const FrameMeasurer measurer(ed, samples, regions, current, base);
    ExpectSameNumbers(measurer.numbers(),
                      MeasureFrame(ed, samples, regions, current, base));
    for (size_t j = 0; j < entries.size(); ++j) {
      Eigen::VectorXd delta = Eigen::VectorXd::Zero(entries.size());
      delta[j] = entries[j].kind == Kind::kCenter ? 0.5 : 0.02;
      const Model moved = Nudged(current, entries, delta);
      SCOPED_TRACE(j);
      const FrameNumbers kept =
          measurer.Moved(moved, MovedRange(current, entries[j]));
      const FrameNumbers fresh =
          MeasureFrame(ed, samples, regions, moved, base);
      ExpectSameNumbers(kept, fresh);
      // A knot's step does move the numbers: the test would see a row or
      // a vertex left as it was.
      if (entries[j].kind != Kind::kKnot) continue;
      EXPECT_GT(std::abs(Flatten(kept)[7] - Flatten(measurer.numbers())[7]) +
                    std::abs(kept.regions[0].ecc_percent -
                             measurer.numbers().regions[0].ecc_percent) +
                    std::abs(kept.regions[15].ecc_percent -
                             measurer.numbers().regions[15].ecc_percent) +
                    std::abs(kept.regions[8].ecc_percent -
                             measurer.numbers().regions[8].ecc_percent),
                1e-6);
    }
  }
}

// Measured against another end-diastole, the frame's kept samples and
// volumes give what measuring from scratch gives.
TEST_P(FrameMeasurerTest, AgainstMeasuresWhatMeasureFrameMeasures) {
  const Model ed = UnevenTestModel(Base(), 1.0, 0.01);
  const Model other_ed = UnevenTestModel(Base(), 1.02, 0.015);
  const Model current = UnevenTestModel(Base(), 0.85, 0.03);
  const ReferenceSamples samples = SampleReference(ed, RegionLayout());
  const ReferenceSamples other = SampleReference(other_ed, RegionLayout());
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  const FrameMeasurer measurer(ed, samples, regions, current, nullptr);
  ReferenceRings other_rings(other_ed);
  ExpectSameNumbers(measurer.Against(other_rings, other, MovedU()),
                    MeasureFrame(other_ed, other, regions, current, nullptr));
  // A knot's step of end-diastole, an inner one and one that moves the
  // apex's height (every row's level): the other frame compared again in
  // the span's rows only, or in all, and end-diastole's own frame moved
  // with its reference.  The samples taken from scratch differ from the
  // kept ones only in those rows (WallMotionTest.
  // ResampleReferenceTakesWhatAStepMoves).
  const FrameMeasurer own(ed, samples, regions, ed, nullptr);
  using Kind = CovarianceEntry::Kind;
  for (const CovarianceEntry& entry : {CovarianceEntry{Kind::kKnot, 5, kA1},
                                       CovarianceEntry{Kind::kKnot, 0, kA3}}) {
    SCOPED_TRACE(entry.knot);
    const Model moved = Nudged(ed, {entry}, Eigen::VectorXd::Constant(1, 0.02));
    const ReferenceSamples moved_samples =
        SampleReference(moved, RegionLayout());
    const MovedU range = MovedRange(ed, entry);
    // The two frames share the moved end-diastole's rings.
    ReferenceRings moved_rings(moved);
    const FrameNumbers against =
        measurer.Against(moved_rings, moved_samples, range);
    ExpectSameNumbers(
        against, MeasureFrame(moved, moved_samples, regions, current, nullptr));
    ExpectSameNumbers(
        own.Moved(moved, range, moved_rings, moved_samples),
        MeasureFrame(moved, moved_samples, regions, moved, nullptr));
    // The step moves the segments of its span's level: a comparison that
    // kept every row would not.
    double change = 0.0;
    for (size_t r = 0; r < against.regions.size(); ++r) {
      change += std::abs(against.regions[r].ecc_percent -
                         measurer.numbers().regions[r].ecc_percent);
    }
    EXPECT_GT(change, 1e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(Walls, FrameMeasurerTest, ::testing::Bool());

// A knot's step moves the model between its neighbours only; the first and
// the last knot's to the ends, the pose's everywhere.
TEST(MovedRangeTest, IsTheKnotsSpan) {
  const Model model = TestSpheroid(9);
  const KnotGrid& grid = model.config.Grid();
  using Kind = CovarianceEntry::Kind;
  const MovedU inner = MovedRange(model, {Kind::kKnot, 3, kA1});
  EXPECT_EQ(inner.low, grid.KnotU(2));
  EXPECT_EQ(inner.high, grid.KnotU(4));
  EXPECT_TRUE(std::isinf(MovedRange(model, {Kind::kKnot, 0, kA1}).low));
  EXPECT_TRUE(std::isinf(MovedRange(model, {Kind::kKnot, 8, kA1}).high));
  const MovedU pose = MovedRange(model, {Kind::kCenter, -1, 0});
  EXPECT_TRUE(std::isinf(pose.low) && std::isinf(pose.high));
  // Only a3 and e3o at an end knot move the apex's or the rim's height.
  EXPECT_TRUE(pose.heights);
  EXPECT_TRUE(MovedRange(model, {Kind::kKnot, 0, kA3}).heights);
  EXPECT_TRUE(MovedRange(model, {Kind::kKnot, 8, kE3o}).heights);
  EXPECT_FALSE(MovedRange(model, {Kind::kKnot, 0, kA1}).heights);
  EXPECT_FALSE(MovedRange(model, {Kind::kKnot, 4, kA3}).heights);
  // Only the pose's steps are rigid.
  EXPECT_TRUE(pose.rigid);
  EXPECT_TRUE(MovedRange(model, {Kind::kRotation, -1, 2}).rigid);
  EXPECT_FALSE(MovedRange(model, {Kind::kGlobal, -1, kA0}).rigid);
  EXPECT_FALSE(MovedRange(model, {Kind::kKnot, 4, kA1}).rigid);
}

}  // namespace
}  // namespace pfdm
