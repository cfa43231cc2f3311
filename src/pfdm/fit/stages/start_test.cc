#include "pfdm/fit/stages/start.h"

#include <string>
#include <utility>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

PointSequence Tags() {
  PointSequence sequence = MakeTestPhantom(500, 3).points;
  sequence.source = "tags.csv";
  return sequence;
}

TEST(StartTest, StartsFromFrameZeroWithTheWallUndecidedForTags) {
  const SequenceStart start =
      StartSequence(Tags(), ModelConfig::Paper(17), FitOptions());
  EXPECT_TRUE(start.has_tags);
  EXPECT_FALSE(start.wall.decided);
  EXPECT_FALSE(start.model.config.Solid());
  EXPECT_EQ(start.frames_per_id.size(), 500u);
  EXPECT_EQ(start.frames_per_id.at(7), 3);
  // The initialized model (InitializeModel) reaches over frame 0's points:
  // a0 spans them, 110 mm long.
  EXPECT_GT(start.model.state.globals[kA0], 40.0);
}

TEST(StartTest, ContoursOfBothWallsStartASolid) {
  PointSequence contours = Tags();
  for (Frame& frame : contours.frames) {
    for (size_t i = 0; i < frame.points.size(); ++i) {
      frame.points[i].id += 1000000 * frame.index;
      frame.points[i].layer =
          i % 2 == 0 ? WallLayer::kEndocardium : WallLayer::kEpicardium;
    }
  }
  const SequenceStart start =
      StartSequence(contours, ModelConfig::Paper(17), FitOptions());
  EXPECT_FALSE(start.has_tags);
  EXPECT_TRUE(start.model.config.Solid());
  EXPECT_EQ(start.wall.reason, "endocardial and epicardial contours");
}

TEST(StartTest, RejectsASequenceWithoutFrames) {
  PointSequence empty;
  empty.source = "tags.csv";
  EXPECT_EQ(InputErrorOf([&] {
              StartSequence(empty, ModelConfig::Paper(17), FitOptions());
            }),
            "tags.csv: no frames");
}

TEST(StartTest, RejectsFramesWithTooFewPoints) {
  PointSequence sequence = Tags();
  sequence.frames[2].points.resize(5);
  EXPECT_EQ(InputErrorOf([&] {
              StartSequence(sequence, ModelConfig::Paper(17), FitOptions());
            }),
            "tags.csv: frame 2: only 5 points, at least 10 needed");
}

// Issue 14: a later frame flattened into a plane "fitted" with exit 0, and
// identical points reached Ceres as NaN.
TEST(StartTest, RejectsFramesThatDoNotSpanSpace) {
  const std::pair<const char*, Eigen::Vector3d> cases[] = {
      {"all at one place", Eigen::Vector3d::Zero()},
      {"on a line", Eigen::Vector3d(0, 0, 1)},
      {"in a plane", Eigen::Vector3d(1, 1, 0)}};
  for (const auto& [what, keep] : cases) {
    PointSequence sequence = Tags();
    for (DataPoint& p : sequence.frames[1].points) {
      p.position = p.position.cwiseProduct(keep) + Eigen::Vector3d(1, 2, 3);
    }
    EXPECT_EQ(InputErrorOf([&] {
                StartSequence(sequence, ModelConfig::Paper(17), FitOptions());
              }),
              std::string("tags.csv: frame 1: the points lie ") + what +
                  "; a surface needs points that span space");
  }
}

}  // namespace
}  // namespace pfdm
