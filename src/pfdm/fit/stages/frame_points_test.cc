#include "pfdm/fit/stages/frame_points.h"

#include "Eigen/Geometry"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

DataPoint Point(std::int64_t id, double x, WallLayer layer) {
  DataPoint p;
  p.id = id;
  p.position = Eigen::Vector3d(x, 2.0 * x, 3.0 * x);
  p.layer = layer;
  return p;
}

// Two tags (ids 1, 2) seen in both frames, and in each frame a contour
// point of each wall (ids seen once).
PointSequence TagsAndContours() {
  PointSequence sequence;
  for (int t = 0; t < 2; ++t) {
    Frame frame;
    frame.index = t;
    frame.points = {Point(1, 1.0, WallLayer::kAnywhere),
                    Point(10 + t, 2.0, WallLayer::kEndocardium),
                    Point(2, 3.0, WallLayer::kAnywhere),
                    Point(20 + t, 4.0, WallLayer::kEpicardium)};
    sequence.frames.push_back(frame);
  }
  return sequence;
}

TEST(FramePointsTest, CountsTheFramesEachIdAppearsIn) {
  const FramesPerId counts = CountFramesPerId(TagsAndContours());
  EXPECT_EQ(counts.size(), 6u);
  EXPECT_EQ(counts.at(1), 2);
  EXPECT_EQ(counts.at(2), 2);
  EXPECT_EQ(counts.at(10), 1);
  EXPECT_EQ(counts.at(21), 1);
}

TEST(FramePointsTest, FrameZeroSearchesEveryPointAndRanksItsTags) {
  const PointSequence sequence = TagsAndContours();
  std::vector<MaterialPoint> material;
  const FramePoints points =
      MakeFramePoints(sequence.frames[0], /*reference=*/true,
                      CountFramesPerId(sequence), {}, &material);
  EXPECT_EQ(points.kind, FrameKind::kReference);
  EXPECT_EQ(points.index, 0);
  EXPECT_EQ(points.untracked, (std::vector<size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(points.tracked.empty());
  EXPECT_EQ(points.is_tag, (std::vector<bool>{true, false, true, false}));
  EXPECT_EQ(points.assign_depth, (std::vector<bool>{true, false, true, false}));
  EXPECT_EQ(points.sliding, (std::vector<bool>{true, true, true, true}));
  EXPECT_EQ(points.layer_w, (std::vector<double>{0.0, -1.0, 0.0, 1.0}));
  EXPECT_EQ(points.positions[3], Eigen::Vector3d(4.0, 8.0, 12.0));
  EXPECT_EQ(material.size(), 4u);
}

TEST(FramePointsTest, ALaterFrameKeepsItsTagsMaterialPoints) {
  const PointSequence sequence = TagsAndContours();
  TrackedMaterial tracked;
  tracked[1] = {0.1, 0.2, 0.3};
  tracked[2] = {0.4, 0.5, -0.6};
  std::vector<MaterialPoint> material;
  const FramePoints points =
      MakeFramePoints(sequence.frames[1], /*reference=*/false,
                      CountFramesPerId(sequence), tracked, &material);
  EXPECT_EQ(points.kind, FrameKind::kTracked);
  EXPECT_EQ(points.tracked, (std::vector<size_t>{0, 2}));
  EXPECT_EQ(points.untracked, (std::vector<size_t>{1, 3}));
  EXPECT_EQ(points.assign_depth, std::vector<bool>(4, false));
  EXPECT_EQ(points.sliding, (std::vector<bool>{false, true, false, true}));
  EXPECT_EQ(material[2].v, 0.5);
  EXPECT_EQ(material[2].w, -0.6);
}

// Contours beside tags in a tracked frame: labelled points, or more than a
// tenth of the frame seen in it alone; a tag lost to one frame is neither.
TEST(FramePointsTest, ContoursBesideTagsInATrackedFrame) {
  const PointSequence sequence = TagsAndContours();
  TrackedMaterial tracked;
  tracked[1] = tracked[2] = {0.1, 0.2, 0.3};
  std::vector<MaterialPoint> material;
  FramePoints points =
      MakeFramePoints(sequence.frames[1], /*reference=*/false,
                      CountFramesPerId(sequence), tracked, &material);
  EXPECT_TRUE(HasContoursBesideTags(points));
  points.layer_w.assign(4, 0.0);  // Unlabelled: half the frame seen once.
  EXPECT_TRUE(HasContoursBesideTags(points));
  points.layer_w.assign(20, 0.0);
  points.is_tag.assign(20, true);
  points.is_tag[7] = false;  // One tag in 20 lost to this frame.
  EXPECT_FALSE(HasContoursBesideTags(points));
  points.kind = FrameKind::kReference;
  points.is_tag[8] = points.is_tag[9] = false;
  EXPECT_FALSE(HasContoursBesideTags(points));
}

TEST(FramePointsTest, AFrameWithoutTrackedPointsIsUntracked) {
  const PointSequence sequence = TagsAndContours();
  std::vector<MaterialPoint> material;
  const FramePoints points =
      MakeFramePoints(sequence.frames[1], /*reference=*/false,
                      CountFramesPerId(sequence), {}, &material);
  EXPECT_EQ(points.kind, FrameKind::kUntracked);
  EXPECT_EQ(points.untracked.size(), 4u);
}

// The eight corners of a 2 x 4 x 6 mm box, turned: standard deviations 1,
// 2 and 3 mm whatever the orientation.
TEST(FramePointsTest, PrincipalSpreadsAreThePointsStandardDeviations) {
  Frame frame;
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  for (int corner = 0; corner < 8; ++corner) {
    DataPoint p;
    p.position =
        turn * Eigen::Vector3d(corner & 1 ? 1 : -1, corner & 2 ? 2 : -2,
                               corner & 4 ? 3 : -3) +
        Eigen::Vector3d(10, 20, 30);
    frame.points.push_back(p);
  }
  const Eigen::Vector3d spreads = PrincipalSpreads(frame);
  EXPECT_NEAR(spreads[0], 1.0, 1e-12);
  EXPECT_NEAR(spreads[1], 2.0, 1e-12);
  EXPECT_NEAR(spreads[2], 3.0, 1e-12);
}

}  // namespace
}  // namespace pfdm
