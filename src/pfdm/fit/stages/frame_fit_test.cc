#include "pfdm/fit/stages/frame_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gtest/gtest.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/fit/stages/apex_coverage.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/start.h"
#include "pfdm/testing/segment_contours_phantom.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// Frame 0 decides the wall, keeps its tags' material points for later
// frames and becomes the reference; frame 1 starts from it and leaves its
// own state to the next frame.
TEST(FrameFitTest, CarriesFrameZeroToTheFramesAfterIt) {
  const PointSequence sequence = MakeTestPhantom(1000, 2).points;
  const FitOptions options;
  SequenceStart start =
      StartSequence(sequence, ModelConfig::Paper(17), options);
  CarriedState carried(start.model);
  const FrameFit first =
      FitFrame(sequence.frames[0], true, start.frames_per_id, options,
               sequence.source, &start.wall, &carried);
  EXPECT_TRUE(start.wall.decided);
  EXPECT_NE(start.wall.reason.find("one surface"), std::string::npos);
  EXPECT_EQ(carried.tracked_material.size(), 1000u);
  EXPECT_EQ(carried.reference.knots, first.state.knots);
  EXPECT_EQ(carried.previous.knots, first.state.knots);
  const std::int64_t id = sequence.frames[0].points[17].id;
  EXPECT_EQ(carried.tracked_material.at(id).u, first.material[17].u);
  EXPECT_NEAR(first.rms_mm, 0.5, 0.1);
  EXPECT_TRUE(first.tracked);  // Its tags recur in frame 1.

  const FrameFit second =
      FitFrame(sequence.frames[1], false, start.frames_per_id, options,
               sequence.source, &start.wall, &carried);
  EXPECT_EQ(second.frame, 1);
  EXPECT_EQ(carried.reference.knots, first.state.knots);
  EXPECT_EQ(carried.previous.knots, second.state.knots);
  EXPECT_EQ(second.correspondence_rounds, 1);  // Tracked: nothing to search.
  EXPECT_EQ(second.termination, "CONVERGENCE");
  // Frame 0's tangential noise and frame 1's add up, to sqrt(3 + 2) 0.5 mm
  // for a perfect model; the local field takes up some of it (FitterTest).
  EXPECT_GT(second.rms_mm, std::sqrt(3.0) * 0.5);
  EXPECT_LT(second.rms_mm, std::sqrt(5.0) * 0.5);
  EXPECT_GT(second.solve_seconds, 0.0);
  EXPECT_TRUE(second.tracked);
}

// Tracked frames share frame 0's material points, so the local field's
// matrix is factorized once for the sequence; each frame's field is the one
// a solver factorizing afresh finds, to round-off (1e-9 mm).
TEST(FrameFitTest, TrackedFramesReuseTheLocalFieldsFactorization) {
  const PointSequence sequence = MakeTestPhantom(1000, 3).points;
  const FitOptions options;
  ASSERT_TRUE(options.local.enabled);
  SequenceStart start =
      StartSequence(sequence, ModelConfig::Paper(17), options);
  CarriedState kept(start.model);
  CarriedState fresh(start.model);
  WallDecision fresh_wall = start.wall;
  for (int t = 0; t < 3; ++t) {
    const FrameFit a = FitFrame(sequence.frames[t], t == 0, start.frames_per_id,
                                options, sequence.source, &start.wall, &kept);
    fresh.local_solver = LocalDirectSolver();
    const FrameFit b = FitFrame(sequence.frames[t], t == 0, start.frames_per_id,
                                options, sequence.source, &fresh_wall, &fresh);
    ASSERT_EQ(a.state.local.values.size(), b.state.local.values.size());
    double worst = 0.0, largest = 0.0;
    for (size_t i = 0; i < a.state.local.values.size(); ++i) {
      worst = std::max(
          worst, std::abs(a.state.local.values[i] - b.state.local.values[i]));
      largest = std::max(largest, std::abs(a.state.local.values[i]));
    }
    EXPECT_LT(worst, 1e-9) << t;
    EXPECT_GT(largest, 0.01) << t;  // A field, not zeros.
  }
  EXPECT_EQ(kept.local_solver.factorizations(), 1);
  EXPECT_EQ(fresh.local_solver.factorizations(), 1);  // Its last frame's.
}

// The same points with ids unique per frame (contours): no frame is
// tracked, frame 0 included, though the model moves as before.
TEST(FrameFitTest, ContoursAreNotTracked) {
  PointSequence sequence = MakeTestPhantom(1000, 2).points;
  for (Frame& frame : sequence.frames) {
    for (DataPoint& p : frame.points) p.id += 1000000 * frame.index;
  }
  const FitOptions options;
  SequenceStart start =
      StartSequence(sequence, ModelConfig::Paper(17), options);
  CarriedState carried(start.model);
  for (int t = 0; t < 2; ++t) {
    const FrameFit fit =
        FitFrame(sequence.frames[t], t == 0, start.frames_per_id, options,
                 sequence.source, &start.wall, &carried);
    EXPECT_FALSE(fit.tracked) << t;
    EXPECT_LT(fit.rms_mm, 1.0) << t;
  }
  EXPECT_TRUE(carried.tracked_material.empty());
}

// Contours without the apex (both walls' of a mid-ventricular segment,
// three short-axis slices): frame 0 holds the start's apex
// (kReferenceContourApexWeight).  Left free, each round slid the model
// toward its base and the length's reset shortened it: here 20 rounds,
// unsettled, RMS 2.5 mm at 0.5 mm noise; held, the rounds settle, and the
// data's lowest point lies 0.42 of the model's length above its apex, as on
// the phantom's mid-wall (slices at 0.30 to 0.72 of its length).
TEST(FrameFitTest, ContoursWithoutTheApexKeepTheStartsApex) {
  const PointSequence sequence = SegmentWallContours();
  const FitOptions options;
  SequenceStart start = StartSequence(sequence, ModelConfig::Paper(9), options);
  ASSERT_FALSE(ApexInData(start.model, Positions(sequence.frames[0])));
  CarriedState carried(start.model);
  const FrameFit fit =
      FitFrame(sequence.frames[0], true, start.frames_per_id, options,
               sequence.source, &start.wall, &carried);
  EXPECT_EQ(fit.unsettled_mm, 0.0);
  EXPECT_LT(fit.correspondence_rounds, options.max_correspondence_rounds);
  EXPECT_LT(fit.rms_mm, 1.0);
  const Model& model = carried.model;
  const Eigen::Vector3d axis = model.Rotation().col(2);
  double lowest = std::numeric_limits<double>::infinity();
  for (const DataPoint& p : sequence.frames[0].points) {
    lowest = std::min(lowest, axis.dot(p.position));
  }
  const double apex =
      axis.dot(Eigen::Vector3d(model.state.center.data())) + ApexHeight(model);
  EXPECT_NEAR((lowest - apex) / AxialLength(model), 0.42, 0.05);
}

}  // namespace
}  // namespace pfdm
